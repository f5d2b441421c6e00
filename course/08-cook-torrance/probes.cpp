// The probes of exercise 08-cook-torrance: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 08 Cook-Torrance --------------------------------------------------------------------

ProbeCase brdfCase(Random& rng, const std::string& group, double roughness, double metallic, double NoV, double NoL) {
    ProbeCase c;
    put(c, 0, rng.colour());
    c.in[3] = float(roughness);
    c.in[4] = float(metallic);
    c.in[5] = 1.0f;
    vec3 n = rng.unitVector();
    put(c, 8, n);
    put(c, 12, rng.around(n, NoV));
    put(c, 16, rng.around(n, NoL));
    c.group = group;
    return c;
}

std::vector<ProbeCase> brdfCases(std::uint64_t seed) {
    Random rng(seed);
    std::vector<ProbeCase> cases;
    // (roughness, metallic, NoV, NoL) drawn NoL first, then NoV, metallic, roughness.
    for (int k = 0; k < 40; ++k) {
        double NoL = rng.range(0.1, 1), NoV = rng.range(0.1, 1);
        double metallic = rng.uniform() < 0.5 ? 0.0 : rng.uniform();
        double roughness = rng.range(0.1, 1);
        cases.push_back(brdfCase(rng, "random", roughness, metallic, NoV, NoL));
    }
    for (int k = 0; k < 8; ++k) {
        double NoL = rng.range(0.2, 1), NoV = rng.range(0.2, 1), roughness = rng.range(0.2, 1);
        cases.push_back(brdfCase(rng, "metal (metallic = 1)", roughness, 1.0, NoV, NoL));
    }
    for (int k = 0; k < 8; ++k) {
        double NoL = rng.range(0.2, 1), NoV = rng.range(0.2, 1), roughness = rng.range(0.2, 1);
        cases.push_back(brdfCase(rng, "dielectric (metallic = 0)", roughness, 0.0, NoV, NoL));
    }
    for (int k = 0; k < 6; ++k) {
        double NoL = rng.range(0.3, 1), NoV = rng.range(0.3, 1), metallic = rng.uniform();
        cases.push_back(brdfCase(rng, "roughness 0 (clamped)", 0.0, metallic, NoV, NoL));
    }
    for (int k = 0; k < 6; ++k) {
        double NoL = rng.range(0.3, 1), roughness = rng.range(0.3, 1);
        cases.push_back(brdfCase(rng, "grazing view", roughness, 0.0, 0.02, NoL));
    }
    for (int k = 0; k < 4; ++k) cases.push_back(brdfCase(rng, "light below the horizon", 0.5, 0.0, 0.7, -rng.range(0.1, 0.9)));
    for (int k = 0; k < 4; ++k) {  // n.v exactly 0 (axis vectors, so float32 agrees): a tangent view
        ProbeCase c = brdfCase(rng, "view exactly at the horizon (n.v = 0)", rng.range(0.2, 1), k % 2, 0.5, 0.5);
        put(c, 8, vec3(0, 0, 1));
        put(c, 12, vec3(1, 0, 0));
        put(c, 16, glm::normalize(vec3(-0.3f, 0.2f, 0.8f)));
        cases.push_back(c);
    }
    return cases;
}

std::vector<ProbeSpec> cookTorranceProbes() {
    ProbeSpec alpha{"ggxAlpha", "ggxAlpha(roughness)", 1};
    for (double r : {0.0, 0.01, R::kMinRoughness, 0.1, 0.3, 0.5, 0.77, 1.0}) {
        ProbeCase c;
        c.in[0] = float(r);
        c.group = r < R::kMinRoughness ? "roughness below MIN_ROUGHNESS (clamped)" : "roughness";
        alpha.cases.push_back(c);
    }
    alpha.expected = [](const ProbeCase& c) { return value(R::ggxAlpha(f(c, 0))); };
    // r * r: one rounding. 0.045 written 0.05 is 23% off at roughness 0.
    alpha.tolerance = standardTolerance;
    alpha.describe = [](const ProbeCase& c) { return "roughness=" + fmt(f(c, 0)); };
    alpha.mistakes = {
        {"highlights far too wide: alpha = roughness instead of roughness^2",
         "alpha = r * r with r = clamp(roughness, MIN_ROUGHNESS, 1) (perceptual roughness, Burley 2012)",
         [](const ProbeCase& c) { return value(R::clampRoughness(f(c, 0))); }},
        {"mirror-like surfaces blow up: roughness is not clamped", "clamp roughness to [MIN_ROUGHNESS, 1] before squaring",
         [](const ProbeCase& c) { return value(double(f(c, 0)) * f(c, 0)); }},
    };

    ProbeSpec f0{"baseReflectance", "baseReflectance(material)", 3};
    Random rng(808);
    for (int k = 0; k < 12; ++k) {
        ProbeCase c;
        put(c, 0, rng.colour());
        c.in[4] = float(k < 3 ? 0.0 : k < 6 ? 1.0 : rng.uniform());
        c.group = "material";
        f0.cases.push_back(c);
    }
    f0.expected = [](const ProbeCase& c) { return value(R::baseReflectance(materialAt(c))); };
    // mix(vec3(0.04), albedo, metallic): two roundings; 0.4 or 0.05 for 0.04
    // is 25% or more off on every dielectric case.
    f0.tolerance = standardTolerance;
    f0.describe = [](const ProbeCase& c) { return "albedo=" + fmt(get(c, 0)) + " metallic=" + fmt(f(c, 4)); };

    auto brdfSpec = [](const std::string& name, std::uint64_t seed) {
        ProbeSpec s{name, name + "(n, v, l, material)", 3};
        s.cases = brdfCases(seed);
        // The specular term follows D, and D of a smooth surface follows h:
        // h = normalize(l + v) in float32 is ~1e-7 rad off, and d ln D / d theta
        // reaches ~4 / alpha = 2000 at roughness 0.045: 2e-4, so 2e-3 relative
        // with margin. No constant of the exercise hides in that slack: pi is
        // in D_GGX (05) and Fd_Lambert (03), checked there, and 0.04 written
        // 0.4 changes F0 tenfold.
        s.tolerance = [](const ProbeCase&) { return std::make_pair(kAbs, 2e-3); };
        s.describe = [](const ProbeCase& c) {
            dvec3 n = get(c, 8), v = get(c, 12), l = get(c, 16), h = glm::normalize(l + v);
            return "n=" + fmt(n) + " v=" + fmt(v) + " l=" + fmt(l) + " h=" + fmt(h) + " NoV=" + fmt(glm::dot(n, v)) +
                   " NoL=" + fmt(glm::dot(n, l)) + " NoH=" + fmt(glm::dot(n, h)) + " VoH=" + fmt(glm::dot(v, h)) +
                   " albedo=" + fmt(get(c, 0)) + " roughness=" + fmt(f(c, 3)) + " metallic=" + fmt(f(c, 4));
        };
        return s;
    };
    ProbeSpec spec = brdfSpec("specularBRDF", 811);
    spec.expected = [](const ProbeCase& c) { return value(R::specularBRDF(get(c, 8), get(c, 12), get(c, 16), materialAt(c))); };
    auto specWith = [](const ProbeCase& c, bool roughFresnel, double denominator) {
        dvec3 n = get(c, 8), v = get(c, 12), l = get(c, 16);
        Material m = materialAt(c);
        double NoL = std::clamp(glm::dot(n, l), 0.0, 1.0);
        if (NoL == 0) return value(dvec3(0));
        double NoV = std::clamp(glm::dot(n, v), 1e-4, 1.0);
        dvec3 h = glm::normalize(l + v);
        double D = R::D_GGX(n, h, R::ggxAlpha(m.roughness)), G = R::G_SchlickGGX(NoV, NoL, m.roughness);
        dvec3 F = roughFresnel ? R::F_SchlickRoughness(R::baseReflectance(m), NoV, m.roughness)
                               : R::F_Schlick(R::baseReflectance(m), glm::dot(v, h));
        return value(D * G * F / (denominator * NoL * NoV));
    };
    spec.mistakes = {
        {"highlights use the roughness-aware Fresnel meant for reflections of the environment",
         "for point lights F = F_Schlick(F0, v.h); F_SchlickRoughness is for the mirror bounces only",
         [=](const ProbeCase& c) { return specWith(c, true, 4); }},
        {"highlights 4 times too bright", "the denominator is 4 NoL NoV", [=](const ProbeCase& c) { return specWith(c, false, 1); }},
    };
    spec.groupHints = {{"light below the horizon", "return vec3(0) when NoL = 0 (no division by zero)"},
                       {"grazing view", "clamp NoV to [1e-4, 1]"},
                       {"view exactly at the horizon (n.v = 0)",
                        "NoV = clamp(n.v, 1e-4, 1): with 0 as the lower bound the specular term divides by zero"}};

    ProbeSpec diff = brdfSpec("diffuseBRDF", 812);
    // (1 - F)(1 - metallic) albedo / pi has no D: F moves with h by at most
    // 5 (1 - F0) per radian, so h's 1e-7 rad and a dozen roundings stay
    // below 2e-6. 2e-5 passes every such form and catches albedo / 3.14
    // written in place of Fd_Lambert (5.1e-4).
    diff.tolerance = [](const ProbeCase&) { return std::make_pair(kAbs, 2e-5); };
    diff.expected = [](const ProbeCase& c) { return value(R::diffuseBRDF(get(c, 8), get(c, 12), get(c, 16), materialAt(c))); };
    diff.mistakes = {
        {"metals still show a diffuse colour", "kd = (1 - F)(1 - metallic): metals have no diffuse lobe",
         [](const ProbeCase& c) {
             dvec3 v = get(c, 12), l = get(c, 16);
             Material m = materialAt(c);
             dvec3 F = R::F_Schlick(R::baseReflectance(m), glm::dot(v, glm::normalize(l + v)));
             return value((1.0 - F) * R::Fd_Lambert(m.albedo));
         }},
        {"diffuse ignores the light reflected specularly (kd = 1 - metallic)", "kd = (1 - F)(1 - metallic)",
         [](const ProbeCase& c) {
             Material m = materialAt(c);
             return value((1.0 - m.metallic) * R::Fd_Lambert(m.albedo));
         }},
    };
    diff.groupHints = {{"metal (metallic = 1)", "metals have no diffuse lobe: multiply kd by (1 - metallic)"}};

    ProbeSpec full = brdfSpec("cookTorranceBRDF", 813);
    full.expected = [](const ProbeCase& c) { return value(R::cookTorranceBRDF(get(c, 8), get(c, 12), get(c, 16), materialAt(c))); };
    return {alpha, f0, spec, diff, full};
}

}  // namespace

RL_UNIT_PROBES { return cookTorranceProbes(); }

}  // namespace rl
