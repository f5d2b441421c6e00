// The probes of exercise 06-geometry: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 06 G -------------------------------------------------------------------------------

std::vector<ProbeSpec> geometryProbes() {
    ProbeSpec g1{"G1_SchlickGGX", "G1_SchlickGGX(NoX, k)", 1};
    Random rng(606);
    for (int k = 0; k < 30; ++k) {
        ProbeCase c;
        c.in[0] = float(k == 0 ? 1.0 : k == 1 ? 1e-4 : rng.range(0.001, 1));
        c.in[1] = float(rng.range(0.13, 0.5));
        c.group = "random";
        g1.cases.push_back(c);
    }
    g1.expected = [](const ProbeCase& c) { return value(R::G1_SchlickGGX(f(c, 0), f(c, 1))); };
    // One fraction: a few ulps. No constant to slip.
    g1.tolerance = standardTolerance;
    g1.describe = [](const ProbeCase& c) { return "NoX=" + fmt(f(c, 0)) + " k=" + fmt(f(c, 1)); };

    ProbeSpec g{"G_SchlickGGX", "G_SchlickGGX(NoV, NoL, roughness)", 1};
    for (int k = 0; k < 50; ++k) {
        ProbeCase c;
        c.in[0] = float(rng.range(1e-4, 1));
        c.in[1] = float(rng.range(1e-3, 1));
        c.in[2] = float(k < 5 ? 0.0 : k < 10 ? 1.0 : rng.range(0, 1));
        c.group = k < 5 ? "roughness 0 (clamped to MIN_ROUGHNESS)" : k < 10 ? "roughness 1" : "random";
        g.cases.push_back(c);
    }
    g.expected = [](const ProbeCase& c) { return value(R::G_SchlickGGX(f(c, 0), f(c, 1), f(c, 2))); };
    // Two G1 and k = (r + 1)^2 / 8: a dozen ulps. 1e-4 catches any other
    // constant in k (8 written 8.5: 6%; 0.045 written 0.05: 1% at roughness 0).
    g.tolerance = standardTolerance;
    g.describe = [](const ProbeCase& c) {
        return "NoV=" + fmt(f(c, 0)) + " NoL=" + fmt(f(c, 1)) + " roughness=" + fmt(f(c, 2));
    };
    auto gWithK = [](const ProbeCase& c, double k) {
        return value(R::G1_SchlickGGX(f(c, 0), k) * R::G1_SchlickGGX(f(c, 1), k));
    };
    g.mistakes = {
        {"the image-based-lighting remapping k = alpha/2 is used for point lights",
         "for direct light k = (r + 1)^2 / 8 (Karis 2013); alpha/2 is for IBL",
         [=](const ProbeCase& c) {
             double r = R::clampRoughness(f(c, 2));
             return gWithK(c, r * r / 2);
         }},
        {"roughness is not clamped", "r = clamp(roughness, MIN_ROUGHNESS, 1) before k = (r + 1)^2 / 8",
         [=](const ProbeCase& c) {
             double r = f(c, 2);
             return gWithK(c, (r + 1) * (r + 1) / 8);
         }},
        {"G is a sum, not a product", "G = G1(NoV) * G1(NoL)",
         [](const ProbeCase& c) {
             double r = R::clampRoughness(f(c, 2)), k = (r + 1) * (r + 1) / 8;
             return value(R::G1_SchlickGGX(f(c, 0), k) + R::G1_SchlickGGX(f(c, 1), k));
         }},
    };
    g.groupHints = {{"roughness 0 (clamped to MIN_ROUGHNESS)", "clamp the roughness to [MIN_ROUGHNESS, 1] first"}};
    return {g1, g};
}

}  // namespace

RL_UNIT_PROBES { return geometryProbes(); }

}  // namespace rl
