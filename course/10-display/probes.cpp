// The probes of exercise 10-display: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 10 display -------------------------------------------------------------------------

std::vector<ProbeSpec> displayProbes() {
    Random rng(1010);
    auto radianceValue = [&]() {
        double scale = std::pow(10.0, rng.range(-3, 1.5));
        return float(scale) * rng.colour();
    };
    ProbeSpec tm{"toneMap", "toneMap(c, op)", 3};
    for (int op = 0; op < 3; ++op)
        for (int k = 0; k < 15; ++k) {
            ProbeCase c;
            put(c, 0, radianceValue());
            c.in[3] = float(op);
            c.group = op == 0 ? "reinhard" : op == 1 ? "exponential" : "none";
            tm.cases.push_back(c);
        }
    tm.expected = [](const ProbeCase& c) { return value(R::toneMap(get(c, 0), ToneMap(int(f(c, 3))))); };
    // Values in [0, 1]; GLSL ES 3.00 allows exp() (3 + 2|x|) ulp of its result
    // (below 1 here, so under 1e-6 for |x| < 8, and exp(-x) < 4e-4 beyond),
    // a division 2.5 ulp: 1e-5 absolute is ~100 ulps of 1. No constant to slip but 1.
    tm.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5, 0.0); };
    tm.describe = [](const ProbeCase& c) { return "c=" + fmt(get(c, 0)) + " op=" + fmt(f(c, 3)); };

    ProbeSpec gm{"encodeGamma", "encodeGamma(c, gamma)", 3};
    for (int k = 0; k < 40; ++k) {
        ProbeCase c;
        // Either side of the sRGB threshold 0.0031308, and between it and the
        // decoding threshold 0.04045 (which a slip may use instead).
        put(c, 0, k % 10 == 0 ? vec3(0.001f, 0.002f, 0.003f) : k % 10 == 5 ? vec3(0.0032f, 0.01f, 0.04f) : rng.colour());
        c.in[3] = float(k < 15 ? 2.2 : k < 25 ? 0.0 : rng.range(1, 3));
        c.group = c.in[3] == 0 ? "sRGB (gamma 0)" : "power gamma";
        gm.cases.push_back(c);
    }
    gm.expected = [](const ProbeCase& c) {
        return value(R::encodeGamma(get(c, 0), f(c, 3), f(c, 3) == 0.0f));
    };
    // pow() is exp2(y log2 x) in GLSL ES 3.00: log2 good to 3 ulp (2^-21
    // absolute on [0.5, 2]), times y <= 1/2.2, then exp2's 3 + 2|x| ulp:
    // under 2e-6 absolute on values in [0, 1]. Each constant of the
    // sRGB curve (12.92, 1.055, 0.055, 2.4, 0.0031308) mistyped moves some
    // case by more than 1e-5.
    gm.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5, 0.0); };
    gm.describe = [](const ProbeCase& c) { return "c=" + fmt(get(c, 0)) + " gamma=" + fmt(f(c, 3)); };
    gm.mistakes = {{"the picture is far too dark: pow(c, gamma) instead of pow(c, 1/gamma)",
                    "encoding for the display raises to 1/gamma: c^(1/2.2) brightens mid-tones",
                    [](const ProbeCase& c) {
                        dvec3 x = get(c, 0);
                        double g = f(c, 3);
                        if (g == 0) return value(R::encodeGamma(x, 2.2, true));  // the sRGB branch is separate
                        return value(dvec3(std::pow(x.x, g), std::pow(x.y, g), std::pow(x.z, g)));
                    }}};
    gm.groupHints = {{"sRGB (gamma 0)", "gamma 0 means the exact sRGB curve: 12.92 c below 0.0031308, "
                                        "1.055 c^(1/2.4) - 0.055 above"}};

    ProbeSpec dp{"displayEncode", "displayEncode(radiance, exposure, op, gamma)", 3};
    for (int k = 0; k < 45; ++k) {
        ProbeCase c;
        put(c, 0, radianceValue());
        c.in[3] = float(k % 5 == 0 ? 1.0 : rng.range(0.25, 4));
        c.in[4] = float(k % 3);
        c.in[5] = float(k % 4 == 0 ? 0.0 : 2.2);
        c.group = "radiance";
        dp.cases.push_back(c);
    }
    auto settingsOf = [](const ProbeCase& c) {
        RenderSettings s;
        s.exposure = f(c, 3);
        s.tonemap = ToneMap(int(f(c, 4)));
        s.gamma = f(c, 5) == 0 ? 2.2 : f(c, 5);
        s.srgb = f(c, 5) == 0;
        return s;
    };
    dp.expected = [=](const ProbeCase& c) { return value(R::displayEncode(get(c, 0), settingsOf(c))); };
    // The two steps above chained on values in [0, 1]: 1e-5 absolute, as there.
    dp.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5, 0.0); };
    dp.describe = [](const ProbeCase& c) {
        return "radiance=" + fmt(get(c, 0)) + " exposure=" + fmt(f(c, 3)) + " op=" + fmt(f(c, 4)) + " gamma=" + fmt(f(c, 5));
    };
    dp.mistakes = {
        {"gamma is applied before tone mapping (washed-out colours)",
         "the order is exposure, tone map, then gamma",
         [=](const ProbeCase& c) {
             RenderSettings s = settingsOf(c);
             dvec3 x = R::encodeGamma(get(c, 0) * s.exposure, s.gamma, s.srgb);
             return value(glm::clamp(R::toneMap(x, s.tonemap), 0.0, 1.0));
         }},
        {"exposure is applied after tone mapping", "multiply by exposure first, then tone map",
         [=](const ProbeCase& c) {  // encodeGamma(toneMap(radiance, op) * exposure, gamma), nothing clamped
             RenderSettings s = settingsOf(c);
             return value(R::encodeGamma(R::toneMap(get(c, 0), s.tonemap) * s.exposure, s.gamma, s.srgb));
         }},
    };
    return {tm, gm, dp};
}

}  // namespace

RL_UNIT_PROBES { return displayProbes(); }

}  // namespace rl
