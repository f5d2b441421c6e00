// The OpenGL render against the double-precision CPU reference, on every
// bundled scene and on random scenes of up to 32 spheres and 8 lights, with
// the budget: at most 0.5% of pixels off by more than 1/255 in any
// channel, mean difference under 0.2/255, PFM median relative difference
// under 1e-4, no NaN or Inf.
#include "core/paths.h"
#include "core/scene_io.h"
#include "core/scene_transform.h"
#include "reference/cpu_reference.h"
#include "render/define_table.h"
#include "render/implementation_facts.h"
#include "render/gl_renderer.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

using namespace rl;

namespace {

// Small sizes keep the suite quick on llvmpipe; every scene still covers
// thousands of pixels.
Scene sized(Scene s, int w = 160, int h = 120) {
    s.render.width = w;
    s.render.height = h;
    return s;
}

void expectWithinBudget(const Rendering& got, const Rendering& expected, const std::string& what) {
    ImageDiff d = compareRenderings(got, expected);
    SCOPED_TRACE(what + ": " + test::describe(d));
    EXPECT_LE(d.offFraction, 0.005);
    EXPECT_LT(d.meanLsb, 0.2);
    EXPECT_LT(d.pfmMedianRel, 1e-4);
    EXPECT_EQ(d.nonFinite, 0);
}

void expectMatchesReference(const Scene& scene, const std::string& what) {
    expectWithinBudget(test::renderGl(scene), ref::renderCpu(scene), what);
}

// A deterministic random scene: spheres in a box in front of the camera,
// lights around it, every material parameter over its whole range.
Scene randomScene(std::uint64_t seed) {
    std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
    auto uniform = [&]() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return double(state >> 11) * 0x1.0p-53;
    };
    auto range = [&](double lo, double hi) { return lo + (hi - lo) * uniform(); };
    Scene s;
    s.camera.position = {range(-1, 1), range(-1, 1), 6};
    s.camera.target = {0, 0, -2};
    s.camera.fovYDegrees = range(35, 70);
    int spheres = 1 + int(uniform() * 32), lights = 1 + int(uniform() * 8);
    for (int i = 0; i < spheres; ++i) {
        Sphere sp;
        sp.center = {range(-3, 3), range(-2, 2), range(-6, 1)};
        sp.radius = range(0.2, 1.0);
        sp.material.albedo = {uniform(), uniform(), uniform()};
        sp.material.roughness = uniform();
        sp.material.metallic = uniform() < 0.3 ? 1.0 : uniform() < 0.5 ? 0.0 : uniform();
        sp.material.ao = range(0.5, 1);
        s.spheres.push_back(sp);
    }
    for (int i = 0; i < lights; ++i) {
        Light l;
        l.position = {range(-6, 6), range(-1, 6), range(-4, 6)};
        l.color = {range(0.5, 1), range(0.5, 1), range(0.5, 1)};
        l.intensity = range(5, 60);
        s.lights.push_back(l);
    }
    s.render.maxBounces = int(uniform() * 4);
    s.render.spp = uniform() < 0.3 ? 4 : 1;
    s.render.background = {range(0, 0.2), range(0, 0.2), range(0, 0.3)};
    s.render.tonemap = ToneMap(int(uniform() * 3));
    s.render.srgb = uniform() < 0.3;
    s.render.exposure = range(0.5, 2);
    return sized(s, 96, 72);
}

}  // namespace

TEST(RenderVsReference, DefaultScene) { expectMatchesReference(sized(defaultScene()), "default scene"); }

TEST(RenderVsReference, EveryBundledScene) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenesDir())) {
        if (entry.path().extension() != ".json") continue;
        expectMatchesReference(sized(loadSceneFile(entry.path().string()).scene), entry.path().filename().string());
        ++count;
    }
    EXPECT_GE(count, 5);  // the four course rows and the lecture scene
}

class RandomScenes : public ::testing::TestWithParam<int> {};

TEST_P(RandomScenes, MatchReference) {
    Scene s = randomScene(std::uint64_t(GetParam()));
    expectMatchesReference(s, "random scene " + std::to_string(GetParam()) + " (" + std::to_string(s.spheres.size()) +
                                  " spheres, " + std::to_string(s.lights.size()) + " lights)");
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomScenes, ::testing::Range(1, 13));

TEST(RenderVsReference, ScaledScenesRenderTheSameImage) {
    Scene base = sized(defaultScene());
    Rendering original = test::renderGl(base);
    for (double s : {1e-3, 1e3}) {
        Rendering scaled = test::renderGl(scaledScene(base, s));
        ImageDiff d = compareRenderings(scaled, original);
        SCOPED_TRACE("scale " + std::to_string(s) + ": " + test::describe(d));
        EXPECT_LE(d.offFraction, 0.005);
        EXPECT_LT(d.meanLsb, 0.2);
        EXPECT_EQ(d.nonFinite, 0);
    }
}

TEST(RenderVsReference, SamplesPerPixelAverageRadianceBeforeDisplay) {
    Scene s = sized(defaultScene(), 64, 48);
    s.render.spp = 9;
    expectMatchesReference(s, "spp 9");
}

TEST(RenderVsReference, EveryToneMapAndGamma) {
    for (ToneMap op : {ToneMap::Reinhard, ToneMap::Exponential, ToneMap::None})
        for (bool srgb : {false, true}) {
            Scene s = sized(defaultScene(), 64, 48);
            s.render.tonemap = op;
            s.render.srgb = srgb;
            s.render.exposure = 2.5;
            expectMatchesReference(s, toneMapName(op) + (srgb ? " srgb" : " gamma 2.2"));
        }
}

// A frame without its radiance (FrameSettings::radiance = false: the live
// view's and the bench's timed frames) draws the same display bytes, and
// readBack() then gives no radiance rather than the last frame's; the next
// frame with it stores fresh radiance again.
TEST(RenderVsReference, ADisplayOnlyFrameDrawsTheSamePicture) {
    Scene scene = sized(loadSceneFile((scenesDir() / "lecture.json").string()).scene, 64, 48);
    const Rendering both = test::renderGl(scene);  // makes the context current
    const Implementation solutions{solutionsDir(), {}};
    auto pictureOf = [&](const Scene& s) {
        return buildPictureProgram(solutions, definesFor(s, implementationFacts(solutions), Purpose::Picture));
    };
    PictureProgram picture = pictureOf(scene);
    GlRenderer renderer;
    renderer.setScene(scene);
    FrameSettings frame = frameFromScene(scene);
    renderer.draw(picture, frame);
    const Rendering first = renderer.readBack();
    ASSERT_FALSE(first.radiance.rgb.empty());
    frame.radiance = false;
    renderer.draw(picture, frame);
    const Rendering displayOnly = renderer.readBack();
    EXPECT_TRUE(displayOnly.radiance.rgb.empty());
    EXPECT_EQ(displayOnly.display.rgb, first.display.rgb);
    // Another background changes the radiance of the sky: drawn with its
    // radiance, the renderer stores the new values, not the first frame's.
    Scene other = scene;
    other.render.background = glm::dvec3(0.5, 0.2, 0.1);
    renderer.setScene(other);
    frame.radiance = true;
    renderer.draw(pictureOf(other), frame);
    const Rendering second = renderer.readBack();
    ASSERT_EQ(second.radiance.rgb.size(), first.radiance.rgb.size());
    EXPECT_NE(second.radiance.rgb, first.radiance.rgb);
    expectWithinBudget(first, both, "the picture program against the program of every view");
}
