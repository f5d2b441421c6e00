// The probes of exercise 07-fresnel: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 07 F -------------------------------------------------------------------------------

std::vector<ProbeSpec> fresnelProbes() {
    ProbeSpec p{"F_Schlick", "F_Schlick(F0, VoH)", 3};
    Random rng(707);
    for (int k = 0; k < 50; ++k) {
        ProbeCase c;
        put(c, 0, k % 5 == 0 ? vec3(0.04f) : k % 5 == 1 ? vec3(1.0f) : rng.colour());
        c.in[3] = float(k < 4 ? 1.0 : k < 8 ? 0.0 : rng.range(0, 1));
        c.group = k < 4 ? "normal incidence (VoH = 1)" : k < 8 ? "grazing (VoH = 0)" : "random";
        p.cases.push_back(c);
    }
    for (int k = 0; k < 6; ++k) {
        ProbeCase c;
        put(c, 0, rng.colour());
        c.in[3] = float(-rng.range(0.01, 0.5));
        c.group = "VoH < 0 (clamped to 0)";
        p.cases.push_back(c);
    }
    p.expected = [](const ProbeCase& c) { return value(R::F_Schlick(get(c, 0), f(c, 3))); };
    // F0 + (1 - F0) m^5: a few ulps, pow(m, 5.0) or exp2(5 log2 m) a few more
    // (3 ulps of exp2(y log2 x)). The only constants are 1 and 5.
    p.tolerance = standardTolerance;
    p.describe = [](const ProbeCase& c) { return "F0=" + fmt(get(c, 0)) + " VoH=" + fmt(f(c, 3)); };
    p.mistakes = {
        {"reflectance above 1 at grazing angles (F0 + (1 + F0)(1 - VoH)^5)",
         "the weight is (1 - F0), not (1 + F0): F = F0 + (1 - F0)(1 - VoH)^5",
         [](const ProbeCase& c) {
             double m = 1 - std::clamp(double(f(c, 3)), 0.0, 1.0);
             return value(get(c, 0) + (1.0 + get(c, 0)) * std::pow(m, 5));
         }},
        {"Fresnel is wrong between normal and grazing incidence ((1 - VoH^5) instead of (1 - VoH)^5)",
         "raise (1 - VoH) to the 5th power, not VoH: (1 - VoH)^5",
         [](const ProbeCase& c) {
             double x = std::clamp(double(f(c, 3)), 0.0, 1.0);
             return value(get(c, 0) + (1.0 - get(c, 0)) * (1 - std::pow(x, 5)));
         }},
    };
    p.groupHints = {{"VoH < 0 (clamped to 0)", "clamp VoH to [0, 1] before (1 - VoH)^5"},
                    {"normal incidence (VoH = 1)", "at VoH = 1, F must equal F0"},
                    {"grazing (VoH = 0)", "at VoH = 0, F must be 1"}};
    return {p};
}

}  // namespace

RL_UNIT_PROBES { return fresnelProbes(); }

}  // namespace rl
