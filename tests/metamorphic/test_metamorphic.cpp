// Metamorphic suite (issue #10): seeded random scenes whose picture must not
// change under scaling (1e-6 to 1e6), translation (up to 1e6) and rotation
// of the whole scene with its camera; and the camera 1000 times farther away
// with the field of view narrowed to frame the same picture (which changes
// the perspective, so there each render is compared with the truth of the
// transformed scene).
//
// Two judges, two budgets (the issue's):
//   * ReferenceTruth: the CPU reference (double, exact self-sphere handling,
//     rounding-sized offsets) against the offset-free long double oracle
//     (exact_oracle.h): at most 0.05% of pixels off by more than 1/255.
//   * GlslVsReference: the GLSL (solutions/) against the CPU reference: at
//     most 0.25% of pixels off by more than 1/255, mean under 0.1/255.
// Each budget is taken over all kRandomScenes pictures of a test together:
// one 48x36 picture has 1728 pixels, so 0.05% of one picture is less than
// a pixel, a quantum too coarse for a rate. A scene that breaks alone is
// still caught: one scene entirely off is 0.5% of the whole, twice the GLSL
// budget and ten times the reference's; each test also caps every single
// picture (kPerSceneCap).
#include "accuracy/accuracy_support.h"
#include "metamorphic/exact_oracle.h"
#include "metamorphic/random_scene.h"
#include "reference/cpu_reference.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace rl::meta {
namespace {

// At least 200 random scenes per test (the issue); 48x36 each.
constexpr int kRandomScenes = 210;

// The issue's budgets.
using rl::meta::kGlslMeanBudget;
using rl::meta::kGlslOffBudget;
using rl::meta::kReferenceOffBudget;

// Any single picture: at most 2% of its pixels (35 of 1728) off. Far above
// what one correct picture shows (float32 silhouettes and contact lines in
// one picture are a few pixels), far below a picture gone wrong (acne,
// leaks, a lost object: 10% and more).
constexpr double kPerSceneCap = 0.02;

struct Tally {
    double cap = kPerSceneCap;  // per picture
    double pixels = 0, off = 0, sumLsb = 0;
    long nonFinite = 0;
    int scenesOff = 0;  // pictures with any pixel off
    int overCap = 0;
    std::vector<std::pair<double, std::string>> worst;  // (off fraction, what)

    void add(const ImageDiff& d, int width, int height, const std::string& what) {
        double n = double(width) * height;
        pixels += n;
        off += d.offFraction * n;
        sumLsb += d.meanLsb * n;
        nonFinite += d.nonFinite;
        scenesOff += d.offFraction > 0;
        overCap += d.offFraction > cap;
        if (d.offFraction > 0) worst.push_back({d.offFraction, what + ": " + acc::describeDiff(d)});
    }
    double offFraction() const { return pixels > 0 ? off / pixels : 0; }
    double meanLsb() const { return pixels > 0 ? sumLsb / pixels : 0; }
    // One line; with `worstScenes`, the 8 worst pictures below it.
    std::string summary(bool worstScenes = false) const {
        char text[240];
        std::snprintf(text, sizeof text, "off %.4f%% mean %.4f/255 over %.0f pixels; %d pictures with pixels off, %d over the %.0f%% cap",
                      100 * offFraction(), meanLsb(), pixels, scenesOff, overCap, 100 * cap);
        std::vector<std::pair<double, std::string>> w = worst;
        std::sort(w.rbegin(), w.rend());
        std::string out = text;
        for (std::size_t k = 0; worstScenes && k < w.size() && k < 8; ++k) out += "\n    " + w[k].second;
        return out;
    }
};

class Metamorphic : public ::testing::TestWithParam<Transform> {};

std::string transformParamName(const ::testing::TestParamInfo<Transform>& info) { return transformName(info.param); }

const std::vector<Transform> kTransforms = {Transform::Identity, Transform::Scale, Transform::Translate,
                                            Transform::Rotate, Transform::FartherCamera};

// ---- the reference against the offset-free oracle ------------------------------------------

class ReferenceTruth : public Metamorphic {};

TEST_P(ReferenceTruth, RandomScenes) {
    Tally tally;
    for (int seed = 0; seed < kRandomScenes; ++seed) {
        Scene scene = randomScene(std::uint64_t(seed));
        std::string what;
        Scene moved = transformed(scene, GetParam(), std::uint64_t(seed), &what);
        // Where the transform keeps the picture, the truth is the untransformed
        // scene's: this checks the reference's invariance and its truth at once.
        Rendering truth = renderOracle(keepsPicture(GetParam()) ? scene : moved);
        Rendering got = ref::renderCpu(moved);
        tally.add(compareRenderings(got, truth), scene.render.width, scene.render.height,
                  describeScene(std::uint64_t(seed), scene) + ", " + what);
    }
    std::printf("[ measured ] reference vs offset-free, %s: %s\n", transformName(GetParam()).c_str(),
                tally.summary(true).c_str());
    EXPECT_EQ(tally.nonFinite, 0);
    EXPECT_LE(tally.offFraction(), kReferenceOffBudget) << tally.summary();
    EXPECT_EQ(tally.overCap, 0) << tally.summary();
}

INSTANTIATE_TEST_SUITE_P(Metamorphic, ReferenceTruth, ::testing::ValuesIn(kTransforms), transformParamName);

// ---- the GLSL against the reference ------------------------------------------------------------

class GlslVsReference : public Metamorphic {};

TEST_P(GlslVsReference, RandomScenes) {
    Tally tally;
    for (int seed = 0; seed < kRandomScenes; ++seed) {
        Scene scene = randomScene(std::uint64_t(seed));
        std::string what;
        Scene moved = transformed(scene, GetParam(), std::uint64_t(seed), &what);
        Rendering expected = ref::renderCpu(keepsPicture(GetParam()) ? scene : moved);
        Rendering got = acc::renderGlsl(moved);
        tally.add(compareRenderings(got, expected), scene.render.width, scene.render.height,
                  describeScene(std::uint64_t(seed), scene) + ", " + what);
    }
    std::printf("[ measured ] GLSL vs reference, %s: %s\n", transformName(GetParam()).c_str(), tally.summary(true).c_str());
    EXPECT_EQ(tally.nonFinite, 0);
    EXPECT_LE(tally.offFraction(), kGlslOffBudget) << tally.summary();
    EXPECT_LT(tally.meanLsb(), kGlslMeanBudget) << tally.summary();
    EXPECT_EQ(tally.overCap, 0) << tally.summary();
}

INSTANTIATE_TEST_SUITE_P(Metamorphic, GlslVsReference, ::testing::ValuesIn(kTransforms), transformParamName);

// ---- the generator itself --------------------------------------------------------------------------

TEST(RandomScenes, AreSeededAndCoverWhatTheIssueAsks) {
    // The same seed gives the same scene; the kinds and ranges the issue
    // lists all occur among the suite's scenes.
    Scene a = randomScene(42), b = randomScene(42);
    ASSERT_EQ(a.spheres.size(), b.spheres.size());
    for (std::size_t k = 0; k < a.spheres.size(); ++k) EXPECT_EQ(a.spheres[k].center, b.spheres[k].center);

    std::size_t maxSpheres = 0, maxLights = 0;
    int maxBounces = 0, minBounces = 99, mirrors = 0, metals = 0, spp4 = 0, spp1 = 0, touching = 0, overlapping = 0;
    double biggest = 0;
    for (int seed = 0; seed < kRandomScenes; ++seed) {
        Scene s = randomScene(std::uint64_t(seed));
        maxSpheres = std::max(maxSpheres, s.spheres.size());
        maxLights = std::max(maxLights, s.lights.size());
        maxBounces = std::max(maxBounces, s.render.maxBounces);
        minBounces = std::min(minBounces, s.render.maxBounces);
        spp4 += s.render.spp == 4;
        spp1 += s.render.spp == 1;
        for (std::size_t i = 0; i < s.spheres.size(); ++i) {
            const Sphere& p = s.spheres[i];
            biggest = std::max(biggest, p.radius);
            mirrors += p.material.metallic == 1 && p.material.roughness == 0.045;
            metals += p.material.metallic == 1 && p.material.roughness > 0.045;
            for (std::size_t j = 0; j < i; ++j) {
                const Sphere& q = s.spheres[j];
                double d = glm::length(p.center - q.center), sum = p.radius + q.radius;
                touching += std::abs(d - sum) <= 1e-12 * sum;
                overlapping += d < 0.99 * sum && d > std::abs(p.radius - q.radius);
            }
        }
        EXPECT_LE(s.spheres.size(), std::size_t(kMaxSpheres)) << seed;
        EXPECT_LE(s.lights.size(), std::size_t(kMaxLights)) << seed;
        EXPECT_NO_THROW(ref::cameraBasis(s.camera)) << seed;
    }
    EXPECT_GE(maxSpheres, 40u);
    EXPECT_EQ(maxLights, 16u);
    EXPECT_EQ(minBounces, 0);
    EXPECT_EQ(maxBounces, 8);
    EXPECT_GT(spp4, 20);
    EXPECT_GT(spp1, 20);
    EXPECT_GT(mirrors, 50);
    EXPECT_GT(metals, 50);
    EXPECT_GT(touching, 200);
    EXPECT_GT(overlapping, 50);
    EXPECT_GE(biggest, 5e4);  // a ground of radius 1e5 occurs
}

TEST(RandomScenes, FrameTheirSpheres) {
    // A scene whose camera sees only the background tests nothing: in every
    // scene at least 5% of the camera rays (one per pixel, 86 of 1728) hit a
    // sphere (a sparse cluster of a few small spheres covers less than 10%).
    int fewest = 100, median = 0;
    std::vector<int> shares;
    for (int seed = 0; seed < kRandomScenes; ++seed) {
        Scene s = randomScene(std::uint64_t(seed));
        ref::CameraBasis camera = ref::cameraBasis(s.camera);
        glm::dvec2 resolution(s.render.width, s.render.height);
        int hits = 0;
        for (int j = 0; j < s.render.height; ++j)
            for (int i = 0; i < s.render.width; ++i) {
                glm::dvec3 d = ref::cameraRayDirection(glm::dvec2(i + 0.5, j + 0.5), resolution, camera.fovYRadians,
                                                       camera.right, camera.up, camera.forward);
                ref::Hit hit;
                hits += ref::closestHit(s, camera.position, d, hit);
            }
        int share = 100 * hits / (s.render.width * s.render.height);
        shares.push_back(share);
        EXPECT_GE(share, 5) << describeScene(std::uint64_t(seed), s);
    }
    std::sort(shares.begin(), shares.end());
    fewest = shares.front();
    median = shares[shares.size() / 2];
    std::printf("[ measured ] camera rays that hit a sphere: fewest %d%%, median %d%%\n", fewest, median);
}

TEST(RandomScenes, TransformsKeepTheScenesMeaning) {
    // Scaling by s scales intensities by s^2 (irradiance C I / d^2 unchanged);
    // rotation keeps distances; the farther camera frames the same rectangle.
    Scene s = randomScene(7);
    Scene big = transformed(s, Transform::Scale, 7);
    double ratio = big.spheres[0].radius / s.spheres[0].radius;
    if (!s.lights.empty()) EXPECT_NEAR(big.lights[0].intensity / s.lights[0].intensity, ratio * ratio, 1e-12 * ratio * ratio);
    Scene turned = rotatedScene(s, 7);
    for (std::size_t k = 1; k < s.spheres.size(); ++k) {
        double d = glm::length(s.spheres[k].center - s.spheres[0].center);
        EXPECT_NEAR(glm::length(turned.spheres[k].center - turned.spheres[0].center), d, 1e-12 * d);  // rounding only
    }
    Scene far = fartherCamera(s, 1000);
    double before = glm::length(s.camera.target - s.camera.position) * std::tan(s.camera.fovYDegrees * M_PI / 360);
    double after = glm::length(far.camera.target - far.camera.position) * std::tan(far.camera.fovYDegrees * M_PI / 360);
    EXPECT_NEAR(after, before, 1e-9 * before);
}

}  // namespace
}  // namespace rl::meta
