// The differential test of the one program (docs/decisions.md, "One
// program"): random hard scenes, each drawn by the program `raylab render`
// builds for it (Purpose::Picture, with its sky tiles' program and the exact
// program for the pixels whose assumption does not hold), for the course's
// files and for a student's complete submission written differently, and
// by the generic program (`raylab render --generic`); every picture is
// judged against the true picture (the long double oracle, exact_oracle.h)
// within the suite's budgets (random_scene.h), and the specialised picture
// must never be off where the generic one is not.
//
// The scenes: the metamorphic suite's random scenes (every kind: clusters,
// huge grounds, touching rows, the camera inside a closed sphere, facing
// mirrors, distant cameras), each scaled by 10^u, u uniform in [-6, 8], and
// moved by up to 10^6 of its size; every fourth seed has the camera put on
// a sphere's surface (from double: on it to within its rounding), every
// third 8 to 16 bounces.
//
// CI runs kCiScenes scenes from a fixed seed; a fresh set on demand:
//   RAYLAB_DIFFERENTIAL_SEED=12345 RAYLAB_DIFFERENTIAL_COUNT=40 \
//       ctest --preset default -R DifferentialFresh --output-on-failure
// (or build/bin/metamorphic_tests --gtest_filter=DifferentialFresh.*, with no
// CTest timeout, for long runs)
// (default count kCiScenes; each failure names the seed that rebuilds its scene).
#include "accuracy/accuracy_support.h"
#include "metamorphic/exact_oracle.h"
#include "metamorphic/random_scene.h"

#include "core/scene_transform.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace rl::meta {
namespace {

constexpr int kCiScenes = 12;                  // 1 to 15 s each on llvmpipe (three programs built per scene)
constexpr std::uint64_t kCiSeed = 20261207;    // the fixed set CI runs
constexpr int kMaxScenes = 1000;               // a fresh run's most

std::uint64_t envNumber(const char* name, std::uint64_t fallback) {
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 10);
    return end && *end == '\0' ? std::uint64_t(value) : fallback;
}

std::uint64_t firstSeed() { return envNumber("RAYLAB_DIFFERENTIAL_SEED", kCiSeed); }
int sceneCount() { return int(std::min<std::uint64_t>(envNumber("RAYLAB_DIFFERENTIAL_COUNT", kCiScenes), kMaxScenes)); }

// The scene of one seed and what was done to it, for the failure message.
struct HardScene {
    Scene scene;
    std::string what;
};

// Which seeds get the camera on a surface and many bounces: every fourth and
// every third (BySeed, the rule of the runs above), or a quarter and a third
// of them drawn by chance (ByChance, the rule of the first fresh runs, whose
// finds are kept below with the scenes they found).
enum class Features { BySeed, ByChance };

HardScene hardScene(std::uint64_t seed, Features features = Features::BySeed) {
    // std::mt19937_64 is the same sequence everywhere; the draws below use
    // its raw output only (no std:: distributions, whose algorithms differ).
    std::mt19937_64 rng(seed);
    auto uniform = [&] { return double(rng() >> 11) * (1.0 / 9007199254740992.0); };
    HardScene out{randomScene(rng()), ""};
    Scene& s = out.scene;
    std::ostringstream what;
    what << describeScene(seed, s);  // "seed N (kind): ..."
    const bool byChance = features == Features::ByChance;
    if (!s.spheres.empty() && (byChance ? uniform() < 0.25 : seed % 4 == 1)) {
        // On a sphere's surface, on the camera's side of it, looking the same way.
        const Sphere& on = s.spheres[std::size_t(rng() % s.spheres.size())];
        glm::dvec3 n = s.camera.position - on.center;
        n = glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0, 1, 0);
        const glm::dvec3 look = s.camera.target - s.camera.position;
        s.camera.position = on.center + on.radius * n;
        s.camera.target = s.camera.position + look;
        what << ", camera on the surface of a sphere of radius " << on.radius;
    }
    if (byChance ? uniform() < 0.33 : seed % 3 == 2) {
        s.render.maxBounces = 8 + int(rng() % 9);
        what << ", " << s.render.maxBounces << " bounces";
    }
    const double scale = std::pow(10.0, -6.0 + 14.0 * uniform());
    s = scaledScene(s, scale);
    const double away = scale * std::pow(10.0, 6.0 * uniform());
    const double z = 2 * uniform() - 1, phi = 6.283185307179586 * uniform(), r = std::sqrt(std::max(0.0, 1 - z * z));
    s = translatedScene(s, away * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z));
    what << ", scaled by " << scale << ", moved by " << away;
    out.what = what.str();
    return out;
}

// Within the suite's budgets of the truth.
bool withinBudget(const ImageDiff& d) {
    return d.nonFinite == 0 && d.offFraction <= kGlslOffBudget && d.meanLsb < kGlslMeanBudget;
}

std::string describe(const ImageDiff& d) {
    return acc::describeDiff(d) + (d.nonFinite ? ", " + std::to_string(d.nonFinite) + " NaN/Inf channels" : "");
}

// The metamorphic suite's bounce limit (random_scene.h): beyond it a path
// between mirrors that face each other is chaotic (each bounce multiplies a
// direction's error), and float32 loses the path long double follows: at 15
// bounces inside a mirror sphere the generic program itself is off on 0.9%
// of the pixels (seed 825). There the picture program is held to the
// generic one's error, not to the truth.
constexpr int kTrueBounces = 8;

void checkSeed(std::uint64_t seed, Features features = Features::BySeed) {
    const HardScene h = hardScene(seed, features);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + h.what);
    std::cout << "[ scene    ] " << h.what << "\n";
    const Rendering truth = renderOracle(h.scene);
    const ImageDiff generic = compareRenderings(acc::renderGlsl(h.scene), truth);
    std::cout << "[ measured ] generic: " << describe(generic) << "\n";
    if (h.scene.render.maxBounces <= kTrueBounces) EXPECT_TRUE(withinBudget(generic)) << "`raylab render --generic`: " << describe(generic);
    for (const auto& [who, impl] : {std::pair<const char*, Implementation>{"the course's files", acc::solutionsWith()},
                                    {"a student's", acc::alternativesSubmission()}}) {
        const ImageDiff d = compareRenderings(acc::renderGlsl(h.scene, impl, true), truth);
        std::cout << "[ measured ] " << who << ": " << describe(d) << "\n";
        if (withinBudget(generic)) {
            EXPECT_TRUE(withinBudget(d)) << "`raylab render` with " << who << ": " << describe(d)
                                         << " where the generic program is within: " << describe(generic);
        } else {  // no worse than the generic program by more than the budget
            EXPECT_EQ(d.nonFinite, 0) << who;
            EXPECT_LE(d.offFraction, generic.offFraction + kGlslOffBudget) << who << ": " << describe(d);
            EXPECT_LT(d.meanLsb, generic.meanLsb + kGlslMeanBudget) << who << ": " << describe(d);
        }
    }
}

class Differential : public ::testing::TestWithParam<int> {};

// The fixed set CI runs, one CTest entry a scene.
TEST_P(Differential, ThePictureProgramIsAsExactAsTheGenericOne) { checkSeed(kCiSeed + std::uint64_t(GetParam())); }

INSTANTIATE_TEST_SUITE_P(Scenes, Differential, ::testing::Range(0, kCiScenes));

// A fresh set on demand (RAYLAB_DIFFERENTIAL_SEED, RAYLAB_DIFFERENTIAL_COUNT),
// one scene after another; skipped unless the seed is given.
TEST(DifferentialFresh, ThePictureProgramIsAsExactAsTheGenericOne) {
    if (firstSeed() == kCiSeed) GTEST_SKIP() << "set RAYLAB_DIFFERENTIAL_SEED for a fresh set";
    for (int index = 0; index < sceneCount(); ++index) checkSeed(firstSeed() + std::uint64_t(index));
}

// Seeds of fresh runs that found something, kept with the rule that drew
// them: 825 (ByChance: 15 bounces inside a mirror sphere, the picture
// program held to the generic one's error), 4269 (BySeed: the camera put on
// the surface of a sphere of radius 1.6e11, 8e9 from the origin: C = |e -
// c|^2 - r^2 rounded in double took the wrong side of the surface in every
// program; now from long double, scene_uniforms.cpp).
struct Found {
    std::uint64_t seed;
    Features features;
};
void PrintTo(const Found& f, std::ostream* out) { *out << f.seed; }  // gtest parameter names

class DifferentialFound : public ::testing::TestWithParam<Found> {};

TEST_P(DifferentialFound, ThePictureProgramIsAsExactAsTheGenericOne) { checkSeed(GetParam().seed, GetParam().features); }

INSTANTIATE_TEST_SUITE_P(Seeds, DifferentialFound,
                         ::testing::Values(Found{825, Features::ByChance}, Found{4269, Features::BySeed}));

}  // namespace
}  // namespace rl::meta
