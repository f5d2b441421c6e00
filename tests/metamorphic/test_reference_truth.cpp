// The CPU reference against the offset-free long double oracle on the
// issue's hard kinds of scene, at a size where a pixel is a small share
// (96x72 = 6912 pixels: the 0.05% budget is 3 pixels), on every scene of
// scenes/hard/, and the closed mirror sphere that must stay black.
#include "accuracy/accuracy_support.h"
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "core/scene_transform.h"
#include "metamorphic/exact_oracle.h"
#include "metamorphic/random_scene.h"
#include "reference/cpu_reference.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rl::meta {
namespace {

using glm::dvec3;

using rl::meta::kReferenceOffBudget;

Material material(dvec3 albedo, double roughness, double metallic) {
    Material m;
    m.albedo = albedo;
    m.roughness = roughness;
    m.metallic = metallic;
    return m;
}

Light light(dvec3 position, double intensity, dvec3 colour = dvec3(1.0)) {
    Light l;
    l.position = position;
    l.intensity = intensity;
    l.color = colour;
    return l;
}

Scene sized(Scene s, int width, int height) {
    s.render.width = width;
    s.render.height = height;
    return s;
}

// The issue's first case: a radius-1 sphere at the origin seen from 3000
// away through a field of view of 0.06 degrees, lit from three sides.
Scene distantCamera() {
    Scene s;
    s.spheres = {sphere(dvec3(0.0), 1.0, material({0.8, 0.3, 0.2}, 0.3, 0.0)),
                 sphere(dvec3(0.9, 0.9, 0.5), 0.35, material({0.9, 0.9, 0.9}, 0.045, 1.0))};
    s.lights = {light({4, 5, 6}, 60), light({-6, 1, 2}, 30, {0.5, 0.6, 1}), light({1, -5, -3}, 20)};
    s.camera.position = {3000 * 0.6, 3000 * 0.0, 3000 * 0.8};
    s.camera.target = dvec3(0.0);
    s.camera.fovYDegrees = 0.06;
    s.render.maxBounces = 2;
    s.render.background = {0.1, 0.1, 0.15};
    return sized(s, 96, 72);
}

// A ground of radius 1e5, spheres resting on it (touching exactly), a
// grazing light 0.05 above the ground 30 away and one overhead.
Scene hugeGroundGrazingLight() {
    const double R = 1e5;
    const dvec3 gc(0, -R, 0);
    auto resting = [&](double r, double x, double z) { return gc + (R + r) * glm::normalize(dvec3(x, 0, z) - gc); };
    Scene s;
    s.spheres = {sphere(gc, R, material({0.8, 0.8, 0.8}, 0.6, 0.0)),
                 sphere(resting(0.5, 0, 0), 0.5, material({0.9, 0.2, 0.1}, 0.4, 0.0)),
                 sphere(resting(0.3, 1.1, 0.4), 0.3, material({0.9, 0.8, 0.5}, 0.2, 1.0)),
                 sphere(resting(0.2, -0.9, 0.6), 0.2, material({0.9, 0.9, 0.9}, 0.045, 1.0))};
    s.lights = {light(resting(0.05, -30, 2), 400), light({1, 6, 2}, 30, {0.7, 0.8, 1})};
    s.camera.position = {0.5, 1.2, 4};
    s.camera.target = {0, 0.3, 0};
    s.camera.fovYDegrees = 45;
    s.render.maxBounces = 2;
    s.render.background = {0.3, 0.35, 0.4};
    return sized(s, 96, 72);
}

// The camera inside a metal sphere of radius 4, three spheres and a light inside.
Scene cameraInside() {
    Scene s;
    s.spheres = {sphere(dvec3(0.0), 4.0, material({0.8, 0.7, 0.6}, 0.2, 1.0)),
                 sphere({0, -1, -1}, 1.0, material({0.2, 0.6, 0.9}, 0.5, 0.0)),
                 sphere({1.5, 0, -1.5}, 0.6, material({0.9, 0.9, 0.9}, 0.045, 1.0)),
                 sphere({0, -4 + 0.7, 0}, 0.7, material({0.9, 0.3, 0.2}, 0.7, 0.0))};  // touching the wall inside
    s.lights = {light({0, 2, 0}, 20)};
    s.camera.position = {0.5, 0.5, 2.5};
    s.camera.target = {0, -0.5, -1};
    s.render.maxBounces = 4;
    s.render.background = {1, 0, 1};  // never visible: the camera is enclosed
    return sized(s, 96, 72);
}

// Two facing mirrors, 8 bounces, a small sphere and a light between them.
Scene facingMirrors() {
    Material mirror = material({0.95, 0.95, 0.95}, 0.045, 1.0);
    Scene s;
    s.spheres = {sphere({-3, 0, 0}, 2, mirror), sphere({3, 0, 0}, 2, mirror),
                 sphere({0, -0.4, 0}, 0.3, material({0.9, 0.4, 0.1}, 0.5, 0.0))};
    s.lights = {light({0, 3, 2}, 20)};
    s.camera.position = {0.3, 0.5, 6};
    s.camera.target = {0, 0, 0};
    s.camera.fovYDegrees = 40;
    s.render.maxBounces = 8;
    s.render.background = {0.4, 0.5, 0.7};
    return sized(s, 96, 72);
}

// The closed mirror sphere of the issue: no light, no ambient, 16 bounces,
// a white background. Every path stays inside and ends after its 17th hit:
// every pixel is exactly black.
Scene closedMirror() {
    Scene s;
    s.spheres = {sphere(dvec3(0.0), 1.0, material({0.98, 0.98, 0.98}, 0.045, 1.0))};
    s.camera.position = {0.2, 0.1, 0.3};
    s.camera.target = {0, 0, -1};
    s.render.maxBounces = 16;
    s.render.ambient = 0;
    s.render.background = {1, 1, 1};
    return sized(s, 96, 72);
}

struct TruthCase {
    std::string name;
    Scene scene;
};

std::vector<TruthCase> truthCases() {
    std::vector<TruthCase> cases = {
        {"distant_camera", distantCamera()},
        {"ground_1e5_grazing_light", hugeGroundGrazingLight()},
        {"ground_1e5_scaled_1em3", scaledScene(hugeGroundGrazingLight(), 1e-3)},
        {"ground_1e5_scaled_1e3", scaledScene(hugeGroundGrazingLight(), 1e3)},
        {"camera_inside", cameraInside()},
        {"facing_mirrors", facingMirrors()},
        {"closed_mirror", closedMirror()},
    };
    // The issue's random scenes of 12-32 touching spheres, 6 lights, spp 4,
    // no bounces, at 96x72, and at the scales 1e-3 and 1e3.
    for (std::uint64_t seed : {2, 8, 14, 20}) {
        Scene s = sized(randomScene(seed), 96, 72);
        cases.push_back({"touching_" + std::to_string(seed), s});
        cases.push_back({"touching_" + std::to_string(seed) + "_scaled_1em3", scaledScene(s, 1e-3)});
        cases.push_back({"touching_" + std::to_string(seed) + "_scaled_1e3", scaledScene(s, 1e3)});
    }
    return cases;
}

void PrintTo(const TruthCase& c, std::ostream* out) { *out << c.name; }  // gtest messages

class TruthCaseTest : public ::testing::TestWithParam<TruthCase> {};

TEST_P(TruthCaseTest, ReferenceMatchesTheOffsetFreeRender) {
    const Scene& scene = GetParam().scene;
    ImageDiff d = compareRenderings(ref::renderCpu(scene), renderOracle(scene));
    std::printf("[ measured ] %s: reference vs offset-free: %s\n", GetParam().name.c_str(), acc::describeDiff(d).c_str());
    EXPECT_EQ(d.nonFinite, 0);
    EXPECT_LE(d.offFraction, kReferenceOffBudget) << acc::describeDiff(d);
}

INSTANTIATE_TEST_SUITE_P(ReferenceTruth, TruthCaseTest, ::testing::ValuesIn(truthCases()),
                         [](const ::testing::TestParamInfo<TruthCase>& info) { return info.param.name; });

// Every scene of scenes/hard/ (whoever adds one): the reference against the
// offset-free render of the same file.
std::vector<std::string> hardSceneFiles() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(scenesDir() / "hard"))
        if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class HardSceneTruth : public ::testing::TestWithParam<std::string> {};

TEST_P(HardSceneTruth, ReferenceMatchesTheOffsetFreeRender) {
    LoadedScene loaded = loadSceneFile((scenesDir() / "hard" / GetParam()).string());
    ImageDiff d = compareRenderings(ref::renderCpu(loaded.scene), renderOracle(loaded.scene));
    std::printf("[ measured ] scenes/hard/%s: reference vs offset-free: %s\n", GetParam().c_str(),
                acc::describeDiff(d).c_str());
    EXPECT_EQ(d.nonFinite, 0);
    EXPECT_LE(d.offFraction, kReferenceOffBudget) << acc::describeDiff(d);
}

INSTANTIATE_TEST_SUITE_P(ReferenceTruth, HardSceneTruth, ::testing::ValuesIn(hardSceneFiles()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// The leak of the issue, the way a user meets it: `raylab render --cpu` of
// a closed mirror sphere with no light writes a black picture (it showed the
// white background on 58% of the pixels while the origin drifted out).
TEST(ReferenceLeak, ClosedMirrorSphereRendersBlackFromTheCommandLine) {
    auto dir = test::freshTempDir("closed_mirror");
    test::writeText(dir / "closed.json", R"({
  "camera": { "position": [0.2, 0.1, 0.3], "target": [0, 0, -1], "fov_y": 60 },
  "render": { "width": 64, "height": 48, "max_bounces": 16, "ambient": 0, "background": [1, 1, 1] },
  "spheres": [ { "center": [0, 0, 0], "radius": 1,
                 "material": { "albedo": [0.98, 0.98, 0.98], "roughness": 0.045, "metallic": 1 } } ]
})");
    auto result = test::runRaylab("render " + (dir / "closed.json").string() + " --cpu -o " + (dir / "closed.png").string() +
                                 " --hdr " + (dir / "closed.pfm").string());
    ASSERT_EQ(result.status, 0) << result.output;
    RadianceImage image = readPfm((dir / "closed.pfm").string());
    ASSERT_EQ(image.width, 64);
    long lit = 0;
    for (float v : image.rgb) lit += v != 0.0f;
    EXPECT_EQ(lit, 0) << "channels with light inside a closed mirror sphere without light";
}

}  // namespace
}  // namespace rl::meta
