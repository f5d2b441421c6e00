// The probes of exercise 03-lambert: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 03 Lambert ------------------------------------------------------------------------

std::vector<ProbeSpec> lambertProbes() {
    ProbeSpec fd{"Fd_Lambert", "Fd_Lambert(albedo)", 3};
    Random rng(303);
    for (int k = 0; k < 20; ++k) {
        ProbeCase c;
        put(c, 0, k == 0 ? vec3(1) : k == 1 ? vec3(0) : rng.colour());
        c.group = "albedo";
        fd.cases.push_back(c);
    }
    fd.expected = [](const ProbeCase& c) { return value(R::Fd_Lambert(get(c, 0))); };
    // albedo / PI is one correctly rounded constant and one division (2.5 ulp
    // in GLSL), or a multiplication by 1.0 / PI (two roundings more): at most
    // ~6 ulp = 4e-7 of the value. 1e-6 relative passes every such form and
    // catches pi written as 3.14 (5e-4) or 3.1416 (2.3e-6). The absolute part,
    // 1e-9, is for albedo 0 and components near it (their ulps are smaller
    // still); kAbs = 1e-6 would hide 3.1416 on every value below 0.43.
    fd.tolerance = [](const ProbeCase&) { return std::make_pair(1e-9, 1e-6); };
    fd.describe = [](const ProbeCase& c) { return "albedo=" + fmt(get(c, 0)); };
    fd.mistakes = {{"diffuse surfaces are pi times too bright", "f_d = albedo / pi: the 1/pi is missing",
                    [](const ProbeCase& c) { return value(get(c, 0)); }}};

    ProbeSpec e{"pointLightIrradiance",
                "pointLightIrradiance(p, n, lightPosition, lightIntensity)", 3};
    auto add = [&](vec3 p, vec3 n, vec3 light, vec3 intensity, const std::string& group) {
        ProbeCase c;
        put(c, 0, p);
        put(c, 4, n);
        put(c, 8, light);
        put(c, 12, intensity);
        c.group = group;
        e.cases.push_back(c);
    };
    for (int k = 0; k < 40; ++k) {
        vec3 p = rng.point(dvec3(-2), dvec3(2));
        vec3 n = rng.unitVector();
        vec3 dir = rng.around(n, rng.range(0.05, 1.0));
        vec3 colour = rng.colour();
        float power = float(rng.range(1, 50));
        add(p, n, p + float(rng.range(0.5, 6)) * dir, power * colour, "light in front");
    }
    for (int k = 0; k < 12; ++k) {
        vec3 n = rng.unitVector();
        vec3 below = rng.around(n, -rng.range(0.1, 1));
        float distance = float(rng.range(0.5, 4));
        add(vec3(1, 2, 3), n, vec3(1, 2, 3) + distance * below, vec3(30), "light behind the surface");
    }
    // The light on the point, or within 1e-6 of it: d2 <= 1e-12 adds nothing
    // (the spec), not only d2 == 0. Distances of 2e-7 to 7e-7 (d2 <= 4.9e-13)
    // and, beyond the threshold, 1.5e-6 to 3e-6 (d2 >= 2.25e-12): far enough
    // from 1e-12 that float32 and double agree on the side. Near the origin,
    // where float32 resolves 1e-7 to a few ulps.
    add(vec3(1, 1, 1), vec3(0, 1, 0), vec3(1, 1, 1), vec3(40), "light on or within 1e-6 of the point");
    for (int k = 0; k < 8; ++k) {
        vec3 p = rng.point(dvec3(-0.25), dvec3(0.25));
        vec3 n = rng.unitVector();
        double distance = k < 5 ? rng.range(2e-7, 7e-7) : rng.range(1.5e-6, 3e-6);
        vec3 colour = rng.colour();
        float power = float(rng.range(1, 50));
        vec3 dir = rng.around(n, rng.range(0.3, 1.0));
        add(p, n, p + float(distance) * dir, power * colour, "light on or within 1e-6 of the point");
    }
    e.expected = [](const ProbeCase& c) {
        return value(R::pointLightIrradiance(get(c, 0), get(c, 4), get(c, 8), get(c, 12)));
    };
    // C I / d2 * NoL: a subtraction, a dot product, an inverse square root
    // and two products, a dozen ulps; 1e-4 relative (kRel). The absolute part
    // follows |C I| for components near zero (grazing light). No constant but
    // the 1e-12 threshold, probed on both sides above.
    e.tolerance = [](const ProbeCase& c) {
        return std::make_pair(kAbs * std::max(1.0, glm::length(get(c, 12))), kRel);
    };
    e.describe = [](const ProbeCase& c) {
        return "p=" + fmt(get(c, 0)) + " n=" + fmt(get(c, 4)) + " light=" + fmt(get(c, 8)) + " CI=" + fmt(get(c, 12));
    };
    e.mistakes = {
        {"light leaks through to the back of surfaces (negative light)",
         "clamp n.l to [0, 1]: a light behind the surface adds nothing",
         [](const ProbeCase& c) {
             dvec3 d = get(c, 8) - get(c, 0);
             double d2 = glm::dot(d, d);
             if (d2 <= 1e-12) return value(dvec3(0));
             return value(get(c, 12) / d2 * glm::dot(get(c, 4), d / std::sqrt(d2)));
         }},
        {"light falls off with distance, not distance squared", "E = C I / d2 * NoL, d2 = |c - p|^2",
         [](const ProbeCase& c) {
             dvec3 d = get(c, 8) - get(c, 0);
             double len = glm::length(d);
             if (len * len <= 1e-12) return value(dvec3(0));
             return value(get(c, 12) / len * std::clamp(glm::dot(get(c, 4), d / len), 0.0, 1.0));
         }},
        {"no falloff with distance", "divide by d2 = |c - p|^2 (inverse-square law)",
         [](const ProbeCase& c) {
             dvec3 d = get(c, 8) - get(c, 0);
             double len = glm::length(d);
             if (len * len <= 1e-12) return value(dvec3(0));
             return value(get(c, 12) * std::clamp(glm::dot(get(c, 4), d / len), 0.0, 1.0));
         }},
    };
    e.mistakes.push_back({"a light within 1e-6 of the point still lights it (d2 == 0 tested, not d2 <= 1e-12)",
                          "return vec3(0) when d2 <= 1e-12: a light that close adds nothing",
                          [](const ProbeCase& c) {
                              dvec3 d = get(c, 8) - get(c, 0);
                              double d2 = glm::dot(d, d);
                              if (d2 == 0) return value(dvec3(0));
                              return value(get(c, 12) / d2 * std::clamp(glm::dot(get(c, 4), d / std::sqrt(d2)), 0.0, 1.0));
                          }});
    e.groupHints = {{"light behind the surface", "clamp n.l at 0: no light from behind"},
                    {"light on or within 1e-6 of the point", "return vec3(0) when d2 <= 1e-12 (no direction, no NaN)"}};
    return {fd, e};
}

}  // namespace

RL_UNIT_PROBES { return lambertProbes(); }

}  // namespace rl
