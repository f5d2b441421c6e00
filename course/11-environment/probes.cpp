// The probes of exercise 11-environment: the cases, the double-precision
// expected values (reference/sh9.h), the float32 tolerances and the mistakes
// the checker names.
#include "checks/probe_toolkit.h"
#include "reference/brdf_reference.h"
#include "reference/sh9.h"

namespace rl {
namespace {

using namespace probes;

// ---- shIrradiance -------------------------------------------------------------------
//
// Inputs (unit.json "probe"): n in a.xyz; nine numbers s_0..s_8 in b, c and
// e.x; the probe sets coefficient k to (s_k, s_(k+3)%9, s_(k+6)%9), so the
// three channels see three different sets.

double coefficientInput(const ProbeCase& c, int k) { return k < 8 ? c.in[4 + k] : c.in[16]; }

R::Sh9 coefficientsOf(const ProbeCase& c) {
    R::Sh9 sh;
    for (int k = 0; k < 9; ++k)
        sh[k] = dvec3(coefficientInput(c, k), coefficientInput(c, (k + 3) % 9), coefficientInput(c, (k + 6) % 9));
    return sh;
}

// E(n) = sum_k A(k) L_k basis_k(n): the mistakes change the basis or the A_l.
dvec3 irradianceWith(const ProbeCase& c, const std::array<double, 9>& basis, const std::array<double, 3>& A) {
    const R::Sh9 sh = coefficientsOf(c);
    dvec3 E(0.0);
    for (int k = 0; k < 9; ++k) E += A[std::size_t(R::sh9Band(k))] * basis[std::size_t(k)] * sh[std::size_t(k)];
    return E;
}

const std::array<double, 3> kA = {R::kPi, 2.0 * R::kPi / 3.0, R::kPi / 4.0};

std::vector<ProbeSpec> irradianceProbes() {
    ProbeSpec p{"shIrradiance", "shIrradiance(n) with L_k = (s_k, s_k+3, s_k+6)", 3};
    Random rng(1101);
    const vec3 axes[6] = {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1)};
    for (int k = 0; k < 60; ++k) {
        ProbeCase c;
        const bool axis = k < 12;
        vec3 n = axis ? axes[k % 6] : rng.unitVector();
        put(c, 0, n);
        for (int i = 0; i < 9; ++i) {
            // A map's own coefficients: the constant term the largest (a radiance is >= 0).
            double s = i == 0 ? rng.range(0.5, 2.0) : rng.range(-0.6, 0.6);
            if (k >= 12 && k < 24 && R::sh9Band(i) != 1 && i != 0) s = 0.0;  // band 1 alone
            if (k >= 24 && k < 36 && R::sh9Band(i) != 2 && i != 0) s = 0.0;  // band 2 alone
            if (i < 8)
                c.in[std::size_t(4 + i)] = float(s);
            else
                c.in[16] = float(s);
        }
        c.group = axis ? "normal along an axis" : k < 24 ? "bands 0 and 1 only" : k < 36 ? "bands 0 and 2 only" : "random";
        p.cases.push_back(c);
    }
    p.expected = [](const ProbeCase& c) { return value(R::sh9Irradiance(coefficientsOf(c), get(c, 0))); };
    // Nine products and sums of terms up to ~6 each: float32 rounding is a
    // few 1e-7 of the largest term, and the GLSL's constants with six digits
    // (0.282095 for 0.28209479...) are off by up to 2e-6 relative. Against
    // the sum of the terms' sizes: 1e-5 of it, far below every mistake.
    p.tolerance = [](const ProbeCase& c) {
        const R::Sh9 sh = coefficientsOf(c);
        double size = 0.0;
        for (int k = 0; k < 9; ++k) size += 4.0 * glm::length(sh[std::size_t(k)]);
        return std::make_pair(1e-5 * size, 1e-5);
    };
    p.describe = [](const ProbeCase& c) {
        std::string s = "n=" + fmt(get(c, 0)) + " s=";
        for (int k = 0; k < 9; ++k) s += (k ? "," : "") + fmt(coefficientInput(c, k));
        return s;
    };
    p.mistakes = {
        {"irradiance too bright and flat: the cosine lobe's A_l are missing (radiance, not irradiance)",
         "multiply band l by the clamped cosine's A_l: A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4",
         [](const ProbeCase& c) { return value(irradianceWith(c, R::sh9Basis(get(c, 0)), {1.0, 1.0, 1.0})); }},
        {"bands 1 and 2 weighted wrongly: A_1 and A_2 swapped",
         "A_1 = 2 pi / 3 (band 1: y, z, x) and A_2 = pi / 4 (band 2)",
         [](const ProbeCase& c) { return value(irradianceWith(c, R::sh9Basis(get(c, 0)), {kA[0], kA[2], kA[1]})); }},
        {"the light comes from the wrong side: the band-1 basis has the wrong sign",
         "Y_1m here are +0.488603 y, +0.488603 z, +0.488603 x, without the minus sign some tables carry "
         "(the host projects the map with the same signs)",
         [](const ProbeCase& c) {
             std::array<double, 9> b = R::sh9Basis(get(c, 0));
             for (int k = 1; k <= 3; ++k) b[std::size_t(k)] = -b[std::size_t(k)];
             return value(irradianceWith(c, b, kA));
         }},
        {"wrong SH constants: band 2's 1.092548 and 0.546274 swapped",
         "the SH constants: 1.092548 for xy, yz, xz; 0.315392 for (3 z^2 - 1); 0.546274 for (x^2 - y^2)",
         [](const ProbeCase& c) {
             dvec3 n = get(c, 0);
             std::array<double, 9> b = R::sh9Basis(n);
             b[4] = 0.546274 * n.x * n.y;
             b[5] = 0.546274 * n.y * n.z;
             b[7] = 0.546274 * n.x * n.z;
             b[8] = 1.092548 * (n.x * n.x - n.y * n.y);
             return value(irradianceWith(c, b, kA));
         }},
    };
    p.groupHints = {{"bands 0 and 1 only", "band 1: A_1 = 2 pi / 3 times 0.488603 (y L_1 + z L_2 + x L_3)"},
                    {"bands 0 and 2 only", "band 2: A_2 = pi / 4 times the five Y_2m with their constants"}};
    return {p};
}

// ---- prefilteredLevel --------------------------------------------------------------

std::vector<ProbeSpec> levelProbes() {
    ProbeSpec p{"prefilteredLevel", "prefilteredLevel(roughness, levels)", 1};
    Random rng(1102);
    for (int k = 0; k < 40; ++k) {
        ProbeCase c;
        const bool outside = k >= 32;
        c.in[0] = float(outside ? (k % 2 ? rng.range(-0.5, -0.01) : rng.range(1.01, 2.0)) : rng.range(0.0, 1.0));
        c.in[1] = float(2 + k % 7);  // 2 to 8 levels
        c.group = outside ? "roughness outside [0, 1] (clamped)" : "roughness in [0, 1]";
        p.cases.push_back(c);
    }
    p.expected = [](const ProbeCase& c) { return value(std::clamp(f(c, 0), 0.0, 1.0) * (f(c, 1) - 1.0)); };
    p.tolerance = standardTolerance;  // one product
    p.describe = [](const ProbeCase& c) { return "roughness=" + fmt(f(c, 0)) + " levels=" + fmt(f(c, 1)); };
    p.mistakes = {
        {"reflections far too sharp: the roughness is used as the level itself",
         "remap the roughness to a level: level k holds roughness k / (levels - 1), so the level is roughness * (levels - 1)",
         [](const ProbeCase& c) { return value(std::clamp(f(c, 0), 0.0, 1.0)); }},
        {"reflections one level too blurry: roughness * levels",
         "levels - 1, not levels: the last level, levels - 1, holds roughness 1",
         [](const ProbeCase& c) { return value(std::clamp(f(c, 0), 0.0, 1.0) * f(c, 1)); }},
        {"reflections too sharp at medium roughness: alpha = roughness^2 used for the level",
         "the levels are spaced in perceptual roughness, not in alpha = roughness^2",
         [](const ProbeCase& c) {
             double r = std::clamp(f(c, 0), 0.0, 1.0);
             return value(r * r * (f(c, 1) - 1.0));
         }},
    };
    p.mistakes.push_back(
        {"the sharpest reflections a little blurry: the roughness clamped to [MIN_ROUGHNESS, 1]",
         "clamp the roughness to [0, 1] here, not [MIN_ROUGHNESS, 1]: level 0 holds roughness 0 (that floor belongs "
         "to alpha, ggxAlpha)",
         [](const ProbeCase& c) { return value(std::clamp(f(c, 0), R::kMinRoughness, 1.0) * (f(c, 1) - 1.0)); }});
    p.groupHints = {{"roughness outside [0, 1] (clamped)",
                     "clamp the roughness to [0, 1] first (to [0, 1] exactly: level 0 holds roughness 0)"}};
    return {p};
}

// ---- environmentShading ------------------------------------------------------------

struct ShadingParts {
    double invPi = 1.0 / R::kPi;
    bool metallicWeight = true;
    bool oneMinusF0 = true;
    bool f0Applied = true;
    bool swapped = false;
};

dvec3 shadingWith(const ProbeCase& c, const ShadingParts& w) {
    Material m = materialAt(c);
    dvec3 F0 = R::baseReflectance(m);
    dvec3 E = get(c, 8), pre = get(c, 12);
    double scale = f(c, 16), bias = f(c, 17);
    if (w.swapped) std::swap(scale, bias);
    dvec3 kd = (w.metallicWeight ? 1.0 - m.metallic : 1.0) * (w.oneMinusF0 ? dvec3(1.0) - F0 : dvec3(1.0));
    dvec3 diffuse = kd * m.albedo * w.invPi * E;
    dvec3 specular = pre * (w.f0Applied ? F0 * scale + bias : dvec3(scale + bias));
    return diffuse + specular;
}

std::vector<ProbeSpec> shadingProbes() {
    ProbeSpec p{"environmentShading", "environmentShading(irradiance, prefiltered, scaleBias, m)", 3};
    Random rng(1103);
    for (int k = 0; k < 60; ++k) {
        ProbeCase c;
        put(c, 0, rng.colour());
        c.in[3] = float(rng.range(0.0, 1.0));
        c.in[4] = float(k % 3 == 0 ? 0.0 : k % 3 == 1 ? 1.0 : rng.range(0.0, 1.0));  // dielectric, metal, between
        c.in[5] = 1.0f;
        put(c, 8, rng.colour() * float(rng.range(0.5, 4.0)));
        put(c, 12, rng.colour() * float(rng.range(0.5, 4.0)));
        // A table's values: scale in [0.3, 1], bias in [0, 0.2] (split_sum.h).
        c.in[16] = float(rng.range(0.3, 1.0));
        c.in[17] = float(rng.range(0.0, 0.2));
        c.group = k % 3 == 0 ? "dielectric (metallic 0)" : k % 3 == 1 ? "metal (metallic 1)" : "metallic between 0 and 1";
        p.cases.push_back(c);
    }
    p.expected = [](const ProbeCase& c) { return value(shadingWith(c, {})); };
    p.tolerance = standardTolerance;  // a dozen products and sums, no transcendental
    p.describe = [](const ProbeCase& c) {
        return "albedo=" + fmt(get(c, 0)) + " metallic=" + fmt(f(c, 4)) + " E=" + fmt(get(c, 8)) +
               " prefiltered=" + fmt(get(c, 12)) + " scale=" + fmt(f(c, 16)) + " bias=" + fmt(f(c, 17));
    };
    auto with = [](ShadingParts w) { return [w](const ProbeCase& c) { return value(shadingWith(c, w)); }; };
    ShadingParts noPi, noMetal, noF0Weight, noF0, swapped;
    noPi.invPi = 1.0;
    noMetal.metallicWeight = false;
    noF0Weight.oneMinusF0 = false;
    noF0.f0Applied = false;
    swapped.swapped = true;
    p.mistakes = {
        {"diffuse environment light too bright by a factor pi: the 1/pi is missing",
         "diffuse = (1 - metallic)(1 - F0) albedo / pi * irradiance: E is irradiance, the Lambert BRDF is albedo / pi",
         with(noPi)},
        {"scale and bias swapped: the split sum's (scale, bias) used as (bias, scale)",
         "specular = prefiltered * (F0 * scale + bias): scaleBias.x is the scale, scaleBias.y the bias", with(swapped)},
        {"Fresnel F0 not applied: every material reflects like a white mirror",
         "multiply the scale by F0 = baseReflectance(m): prefiltered * (F0 * scale + bias)", with(noF0)},
        {"metals get diffuse environment light: the (1 - metallic) is missing",
         "a metal has no diffuse part: diffuse = (1 - metallic)(1 - F0) albedo / pi * irradiance", with(noMetal)},
        {"diffuse a few percent too bright: the (1 - F0) is missing",
         "what the specular reflects is not diffused: diffuse = (1 - metallic)(1 - F0) albedo / pi * irradiance",
         with(noF0Weight)},
    };
    p.groupHints = {{"metal (metallic 1)", "a metal: no diffuse part, F0 = albedo"},
                    {"dielectric (metallic 0)", "a dielectric: F0 = 0.04, diffuse (1 - 0.04) albedo / pi * irradiance"}};
    return {p};
}

}  // namespace

RL_UNIT_PROBES {
    std::vector<ProbeSpec> all = irradianceProbes();
    for (auto* more : {&levelProbes, &shadingProbes})
        for (ProbeSpec& p : more()) all.push_back(std::move(p));
    return all;
}

}  // namespace rl
