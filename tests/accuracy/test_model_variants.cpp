// The model variants of shaders/model_variants.glsl (docs/model-variants.md):
// which defines a scene's "model" compiles in, that the reference model
// compiles nothing in, and that every GLSL term agrees with the
// double-precision CPU reference (app/reference/brdf_reference.h) on random
// and hard inputs.
#include "accuracy/accuracy_support.h"

#include "core/paths.h"
#include "core/scene_io.h"
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"
#include "render/define_table.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace rl;
using glm::dvec3;
using glm::vec3;

// ---- which defines ------------------------------------------------------------------------

TEST(ModelDefines, ReferenceModelCompilesNothingIn) {
    // No define at all: the reference shader is the one it was before the
    // variants existed, and every reference scene shares one program.
    EXPECT_TRUE(modelDefines(ShadingModel{}).empty());
    Scene scene = loadSceneFile((scenesDir() / "lecture.json").string()).scene;
    EXPECT_TRUE(definesFor(scene, ImplementationFacts{}, Purpose::Generic).empty());
}

TEST(ModelDefines, EachSwitchHasItsDefine) {
    struct Expectation {
        std::string name;
        std::string define;
    };
    const Expectation expected[] = {{"beckmann", "RL_D_BECKMANN"},
                                    {"smith-ggx", "RL_G_SMITH_SEPARABLE"},
                                    {"smith-ggx-correlated", "RL_G_SMITH_CORRELATED"},
                                    {"dielectric", "RL_F_DIELECTRIC"},
                                    {"conductor", "RL_F_CONDUCTOR"},
                                    {"burley", "RL_FD_BURLEY"},
                                    {"blinn-phong", "RL_BLINN_PHONG"}};
    std::vector<acc::NamedModel> models = acc::everyModelVariant();
    for (const Expectation& e : expected) {
        auto it = std::find_if(models.begin(), models.end(), [&](const auto& m) { return m.name == e.name; });
        ASSERT_NE(it, models.end()) << e.name;
        ShaderDefines defines = modelDefines(it->model);
        EXPECT_EQ(defines.size(), 2u) << e.name;  // the switch and RL_MODEL_VARIANTS
        EXPECT_EQ(defines.count(e.define), 1u) << e.name;
        EXPECT_EQ(defines.count("RL_MODEL_VARIANTS"), 1u) << e.name;
    }
    ShadingModel all = models.back().model;  // beckmann+correlated+conductor+burley
    EXPECT_EQ(modelDefines(all).size(), 5u);
}

TEST(ModelDefines, BlinnPhongIgnoresTheOtherSwitches) {
    // As the CPU reference does: Blinn-Phong replaces the whole BRDF.
    ShadingModel a, b;
    a.blinnPhong = b.blinnPhong = true;
    b.distribution = DistributionModel::Beckmann;
    b.fresnel = FresnelModel::Conductor;
    EXPECT_EQ(modelDefines(a), modelDefines(b));
}

// ---- the scene field reaches the picture ---------------------------------------------------

TEST(ModelVariants, SceneFieldSelectsTheVariantInTheShader) {
    // The lecture scene with a "model" object: the GLSL picture changes with
    // each variant, and each matches the CPU reference of the same variant.
    const std::string models[] = {
        R"({"distribution": "beckmann"})",       R"({"geometry": "smith-ggx"})",
        R"({"geometry": "smith-ggx-correlated"})", R"({"fresnel": "dielectric"})",
        R"({"fresnel": "conductor"})",           R"({"diffuse": "burley"})",
        R"({"blinn_phong": true})",
        R"({"distribution": "beckmann", "geometry": "smith-ggx-correlated", "fresnel": "conductor", "diffuse": "burley"})"};
    std::ifstream in(scenesDir() / "lecture.json");
    std::string lecture((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Scene reference = parseScene(lecture, "lecture").scene;
    reference.render.width = 96;
    reference.render.height = 72;
    Rendering referencePicture = acc::renderGlsl(reference);
    for (const std::string& model : models) {
        std::string text = lecture;
        text.insert(text.find('{') + 1, "\"model\": " + model + ",");
        LoadedScene loaded = parseScene(text, "lecture with model");
        ASSERT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
        Scene scene = loaded.scene;
        ASSERT_FALSE(scene.model.isReference()) << model;
        scene.render.width = 96;
        scene.render.height = 72;
        Rendering gl = acc::renderGlsl(scene);
        EXPECT_NE(gl.display.rgb, referencePicture.display.rgb) << model << " renders like the reference model";
        ImageDiff d = compareRenderings(gl, ref::renderCpu(scene));
        EXPECT_LE(d.offFraction, 0.0025) << model << ": " << acc::describeDiff(d);
        EXPECT_EQ(d.nonFinite, 0) << model;
    }
}

// ---- every term against double precision ------------------------------------------------------

// splitmix64: the same cases on every platform.
struct Random {
    std::uint64_t state;
    explicit Random(std::uint64_t seed) : state(seed) {}
    double uniform() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // A unit vector at angle acos(cosTheta) from n, random azimuth.
    dvec3 around(dvec3 n, double cosTheta) {
        dvec3 t = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
        dvec3 b = glm::cross(n, t);
        double s = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), phi = range(0, 2 * ref::kPi);
        return cosTheta * n + s * std::cos(phi) * t + s * std::sin(phi) * b;
    }
    dvec3 unit() { return around(dvec3(0, 0, 1), range(-1, 1)); }
};

vec3 asFloat(dvec3 v) { return vec3(glm::normalize(v)); }

// Random and hard inputs: grazing view and light (down to NoV = 1e-3 and the
// clamp at 1e-4), the mirror direction (the peak of the lobe) and near it, the
// roughness clamp, F0 = 1, edge tints 0 and 1.
std::vector<acc::BrdfCase> brdfCases() {
    Random rng(606);
    std::vector<acc::BrdfCase> cases;
    const double cosines[] = {1.0, 0.9, 0.5, 0.1, 1e-2, 1e-3, 5e-5};
    for (int k = 0; k < 600; ++k) {
        acc::BrdfCase c;
        dvec3 n = rng.unit();
        double NoV = k % 3 == 0 ? cosines[k / 3 % 7] : rng.range(0.001, 1.0);
        dvec3 v = rng.around(n, NoV);
        dvec3 l;
        if (k % 5 == 0) {
            l = glm::reflect(-v, n);  // the peak: h = n
        } else if (k % 5 == 1) {
            l = glm::normalize(glm::reflect(-v, n) + rng.range(1e-4, 1e-2) * rng.unit());  // near the peak
            if (glm::dot(l, n) <= 0.0) l = rng.around(n, rng.range(0.01, 1.0));
        } else {
            l = rng.around(n, k % 7 == 0 ? cosines[k / 7 % 6] : rng.range(0.001, 1.0));
        }
        c.n = asFloat(n);
        c.v = asFloat(v);
        c.l = asFloat(l);
        const float roughness[] = {0.0f, 0.045f, 1.0f};
        c.roughness = k % 4 == 0 ? roughness[k / 4 % 3] : float(rng.range(0.0, 1.0));
        c.metallic = k % 3 == 1 ? 1.0f : k % 3 == 2 ? 0.0f : float(rng.uniform());
        c.albedo = k % 11 == 0 ? vec3(1.0f) : vec3(float(rng.uniform()), float(rng.uniform()), float(rng.uniform()));
        c.edgeTint = k % 13 == 0 ? vec3(0.0f) : k % 13 == 1 ? vec3(1.0f)
                                              : vec3(float(rng.uniform()), float(rng.uniform()), float(rng.uniform()));
        cases.push_back(c);
    }
    return cases;
}

// float32 against double. Each term chains 10 to 60 operations with
// condition numbers up to ~100 (D near the peak: 2 theta/alpha^2 dtheta;
// exp(-tan^2/alpha^2) in Beckmann; the Fresnel inversion near F0 = 1), so
// 2e-3 relative is ~3e4 float ulps: far above a right float32 answer, far
// below any wrong formula. The absolute floor 1e-5 is for values that are
// (nearly) zero.
constexpr double kRelative = 2e-3;
constexpr double kAbsolute = 1e-5;

// One input is ill-conditioned in itself: with light and view grazing from
// opposite sides, l + v is short, and its float sum (~1e-7 absolute error per
// component) gives h and VoH = v.h an error of ~1e-7 / |l + v|, which
// F(VoH) and kd = 1 - F pass on times ~5 (d/dVoH of (1 - VoH)^5) on a lobe of
// size albedo/pi < 1: 1e-6 / |l + v| more absolute error (1e-2 at |l + v| = 1e-4).
double conditioningAllowance(const acc::BrdfCase& c) { return 1e-6 / std::max(1e-30, double(glm::length(c.l + c.v))); }

const acc::BrdfProbe kProbes[] = {acc::BrdfProbe::Brdf, acc::BrdfProbe::Specular, acc::BrdfProbe::Diffuse,
                                  acc::BrdfProbe::D, acc::BrdfProbe::F};
const char* const kProbeNames[] = {"brdf", "specular", "diffuse", "D", "F"};

class ModelVariantProbe : public ::testing::TestWithParam<acc::NamedModel> {};

TEST_P(ModelVariantProbe, Float32MatchesDouble) {
    const ShadingModel& model = GetParam().model;
    std::vector<acc::BrdfCase> cases = brdfCases();
    for (int p = 0; p < 5; ++p) {
        if (kProbes[p] == acc::BrdfProbe::F && model.blinnPhong) continue;  // Blinn-Phong has no F term
        std::vector<vec3> got = acc::runBrdfProbe(kProbes[p], cases, model);
        int failures = 0;
        double worst = 0;  // largest error / tolerance
        std::size_t worstCase = 0;
        for (std::size_t k = 0; k < cases.size(); ++k) {
            dvec3 expected = acc::expectedBrdf(kProbes[p], cases[k], model);
            for (int c = 0; c < 3; ++c) {
                double error = std::fabs(got[k][c] - expected[c]);
                double tolerance = kAbsolute + conditioningAllowance(cases[k]) + kRelative * std::fabs(expected[c]);
                bool ok = std::isfinite(got[k][c]) && error <= tolerance;
                if (error / tolerance > worst) {
                    worst = error / tolerance;
                    worstCase = k;
                }
                if (!ok && ++failures <= 5)
                    ADD_FAILURE() << kProbeNames[p] << " case " << k << " channel " << c << ": got " << got[k][c]
                                  << ", double " << expected[c] << " (NoV " << glm::dot(cases[k].n, cases[k].v)
                                  << ", NoL " << glm::dot(cases[k].n, cases[k].l) << ", roughness "
                                  << cases[k].roughness << ", metallic " << cases[k].metallic << ")";
            }
        }
        const acc::BrdfCase& w = cases[worstCase];
        std::cout << "[ measured ] " << GetParam().name << " " << kProbeNames[p] << ": largest error / tolerance " << worst
                  << " (case " << worstCase << ": NoV " << glm::dot(w.n, w.v) << ", NoL " << glm::dot(w.n, w.l)
                  << ", roughness " << w.roughness << ")\n";
        EXPECT_EQ(failures, 0) << kProbeNames[p];
    }
}

std::string testName(const ::testing::TestParamInfo<acc::NamedModel>& info) { return acc::modelTestName(info.param); }

INSTANTIATE_TEST_SUITE_P(Models, ModelVariantProbe, ::testing::ValuesIn(acc::referenceAndVariants()), testName);

TEST(ModelVariants, ExactFresnelIsOneAtEveryAngleForF0One) {
    // F0 = 1 (albedo 1, metallic 1) is where the exact Fresnel terms invert
    // into an infinite index of refraction: the GLSL clamps 1 - F0 at 1e-6
    // and must give 1 (within that clamp) at every angle, finite.
    for (const char* which : {"dielectric", "conductor"}) {
        ShadingModel model;
        model.fresnel = std::string(which) == "dielectric" ? FresnelModel::Dielectric : FresnelModel::Conductor;
        std::vector<acc::BrdfCase> cases;
        for (double VoH : {1.0, 0.7, 0.3, 0.05, 0.0}) {
            for (vec3 tint : {vec3(0.0f), vec3(0.5f), vec3(1.0f)}) {
                acc::BrdfCase c;
                c.v = vec3(0, 0, 1);
                c.l = vec3(float(std::sqrt(1 - VoH * VoH)), 0, float(VoH));  // h, at angle acos(VoH) from v
                c.albedo = vec3(1.0f);
                c.metallic = 1.0f;
                c.edgeTint = tint;
                cases.push_back(c);
            }
        }
        std::vector<vec3> got = acc::runBrdfProbe(acc::BrdfProbe::F, cases, model);
        for (std::size_t k = 0; k < cases.size(); ++k)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[k][c], 1.0, 1e-5) << which << " case " << k;
    }
}

}  // namespace
