// The probes of exercise 09-reflections: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 09 reflections ----------------------------------------------------------------------

// The nearest hit from o along unit d, the sphere `leaving` handled as the
// framework does (intersect_scene.glsl): skipped when the ray leaves its
// outside, its far root from inside. Returns the sphere, -1 for none.
int closestHitLeaving(const Scene& scene, dvec3 o, dvec3 d, int leaving, R::Hit& hit) {
    hit.sphere = -1;
    hit.t = 1e300;
    for (int i = 0; i < int(scene.spheres.size()); ++i) {
        const Sphere& s = scene.spheres[i];
        double t = R::intersectSphere(o, d, s.center, s.radius);
        if (i == leaving) {
            double b = glm::dot(o - s.center, d);
            t = b >= 0 ? -1.0 : -b + std::sqrt(std::max(0.0, b * b - (glm::dot(o - s.center, o - s.center) - s.radius * s.radius)));
        }
        if (t > 0 && t < hit.t) {
            hit.t = t;
            hit.sphere = i;
        }
    }
    if (hit.sphere < 0) return -1;
    // Filled as the CPU reference's makeHit() does: shadeHit() tests the
    // light from inside a sphere (a bounce that went into it) by `inside`.
    const Sphere& s = scene.spheres[hit.sphere];
    dvec3 u = glm::normalize(o + hit.t * d - s.center);
    hit.inside = glm::dot(u, d) > 0;
    hit.p = s.center + s.radius * u;
    hit.n = hit.inside ? -u : u;
    auto maxAbs = [](dvec3 v) { return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))); };
    hit.magnitude = std::max(maxAbs(hit.p), maxAbs(s.center) + s.radius);  // the CPU reference's own shadow offset
    hit.error = 32 * 0x1.0p-53 * (maxAbs(s.center) + s.radius);              // and its kHitErrorRelative (double)
    return hit.sphere;
}

// A local trace loop with switches for the typical mistakes of exercise 09.
// backgroundAfterLimit: the background added once more after the last
// bounce too, as if the path escaped there (the background term after the loop).
dvec3 traceVariant(const Scene& scene, dvec3 origin, dvec3 dir, bool attenuate, bool swapReflect,
                   bool backgroundAfterLimit = false) {
    dvec3 radiance(0), throughput(1);
    int leaving = -1;
    for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce) {
        R::Hit hit;
        dir = glm::normalize(dir);  // closestHit() renormalises
        if (closestHitLeaving(scene, origin, dir, leaving, hit) < 0) {
            radiance += throughput * scene.render.background;
            return radiance;
        }
        radiance += throughput * R::shadeHit(scene, hit, -dir);
        const Material& m = scene.spheres[hit.sphere].material;
        double NoV = std::clamp(glm::dot(hit.n, -dir), 1e-4, 1.0);
        if (attenuate) throughput *= R::F_SchlickRoughness(R::baseReflectance(m), NoV, m.roughness);
        origin = hit.p;
        dir = swapReflect ? hit.n - 2 * glm::dot(dir, hit.n) * dir : glm::reflect(dir, hit.n);
        leaving = hit.sphere;
    }
    if (backgroundAfterLimit) radiance += throughput * scene.render.background;
    return radiance;
}

std::vector<ProbeSpec> reflectionProbes() {
    ProbeSpec fr{"F_SchlickRoughness", "F_SchlickRoughness(F0, NoV, roughness)", 3};
    Random rng(909);
    for (int k = 0; k < 40; ++k) {
        ProbeCase c;
        put(c, 0, k % 4 == 0 ? vec3(0.04f) : rng.colour());
        c.in[3] = float(k < 5 ? 1.0 : k < 10 ? 1e-4 : rng.range(0, 1));
        c.in[4] = float(k % 7 == 0 ? 0.0 : rng.range(0, 1));
        c.group = k < 5 ? "normal incidence" : k < 10 ? "grazing" : "random";
        fr.cases.push_back(c);
    }
    fr.expected = [](const ProbeCase& c) { return value(R::F_SchlickRoughness(get(c, 0), f(c, 3), f(c, 4))); };
    // As F_Schlick, a few ulps; 0.045 written 0.05 moves max(1 - r, F0) by
    // 5e-3 at roughness 0, seen at grazing incidence (1 - NoV)^5 ~ 1.
    fr.tolerance = standardTolerance;
    fr.describe = [](const ProbeCase& c) {
        return "F0=" + fmt(get(c, 0)) + " NoV=" + fmt(f(c, 3)) + " roughness=" + fmt(f(c, 4));
    };
    fr.mistakes = {{"rough surfaces reflect as strongly as smooth ones at grazing angles",
                    "Fr = F0 + (max(1 - r, F0) - F0)(1 - NoV)^5: plain Schlick ignores roughness",
                    [](const ProbeCase& c) { return value(R::F_Schlick(get(c, 0), f(c, 3))); }}};

    ProbeSpec tr{"traceRay", "traceRay(origin, dir) in the probe scene", 3};
    tr.needsScene = true;
    Scene scene = probeScene();
    for (int k = 0; k < 60; ++k) {
        ProbeCase c;
        dvec3 origin = rng.dpoint(dvec3(-4, 1.5, 5), dvec3(4, 5, 9));
        int target = 1 + k % 3;  // aim at the middle of a sphere: no silhouettes, where float and double part ways
        dvec3 aim = scene.spheres[target].center + 0.5 * scene.spheres[target].radius * dvec3(rng.unitVector());
        put(c, 0, vec3(origin));
        put(c, 4, glm::normalize(vec3(aim - origin)));
        c.group = target == 2 ? "metal sphere (bounces)" : "scene ray";
        tr.cases.push_back(c);
    }
    for (int k = 0; k < 12; ++k) {  // between the facing mirrors: the bounce limit decides
        ProbeCase c;
        // Convex mirrors spread rays apart, so only rays very near the axis
        // bounce more than max_bounces times before they escape.
        double z = rng.range(-1e-6, 1e-6), y = rng.range(-1e-6, 1e-6), x = rng.range(10.5, 11.5);
        vec3 origin(float(x), 3.0f + float(y), float(z));
        put(c, 0, origin);
        put(c, 4, vec3(k % 2 ? 1.0f : -1.0f, 0.0f, 0.0f));
        c.group = "between two facing mirrors";
        tr.cases.push_back(c);
    }
    tr.expected = [scene](const ProbeCase& c) { return value(R::traceRadiance(scene, get(c, 0), get(c, 4))); };
    // Three bounces of float32 shading, each ~1e-4: 1e-3 relative.
    tr.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5, 1e-3); };
    // The ray, and what it meets first: enough to follow the trace by hand
    // (the probe scene is probeScene() in app/checks/probe_cases.cpp).
    tr.describe = [scene](const ProbeCase& c) {
        std::string text = "origin=" + fmt(get(c, 0)) + " dir=" + fmt(get(c, 4));
        R::Hit hit;
        if (!R::closestHit(scene, get(c, 0), get(c, 4), hit)) return text + " misses every sphere";
        const Material& m = scene.spheres[hit.sphere].material;
        dvec3 v = -get(c, 4);
        return text + "; first hit: sphere " + std::to_string(hit.sphere) + " at t=" + fmt(hit.t) + " p=" + fmt(hit.p) +
               " n=" + fmt(hit.n) + " v=" + fmt(v) + " NoV=" + fmt(glm::dot(hit.n, v)) + " albedo=" + fmt(m.albedo) +
               " roughness=" + fmt(m.roughness) + " metallic=" + fmt(m.metallic) + " reflected dir=" +
               fmt(glm::reflect(get(c, 4), hit.n));
    };
    tr.mistakes = {
        {"reflections are as bright as the surfaces they show (throughput never attenuated)",
         "after each hit: throughput *= F_SchlickRoughness(F0, NoV, roughness)",
         [scene](const ProbeCase& c) { return value(traceVariant(scene, get(c, 0), get(c, 4), false, false)); }},
        {"reflections point the wrong way (reflect() arguments swapped)",
         "reflect(I, N) takes the incident direction first: reflect(dir, hit.n)",
         [scene](const ProbeCase& c) { return value(traceVariant(scene, get(c, 0), get(c, 4), true, true)); }},
    };
    // probe.glsl marks a case whose bounce starts off offsetRayOrigin(hit.p,
    // hit.n, hit.error) with PROBE_WRONG_ORIGIN (-2): every ray that hits
    // something bounces (maxBounces = 3), so the mistake marks each of them.
    tr.mistakes.push_back({"the bounce starts off the normal (pushed along the reflected ray): the probe reads -2",
                           "continue from offsetRayOrigin(hit.p, hit.n, hit.error): along the normal, whatever the new direction",
                           [scene](const ProbeCase& c) {
                               // offsetRayOrigin(hit.p, r, hit.error) = p + dot(|r|, e) r, with
                               // the first hit's error as closestHit() has it (centre form: the
                               // probe rays hit spheres 1 to 5), marked as probe.glsl does: over
                               // a quarter of the offset dot(|n|, e) from p + dot(|n|, e) n.
                               R::Hit hit;
                               dvec3 d = glm::normalize(get(c, 4));
                               if (closestHitLeaving(scene, get(c, 0), d, -1, hit) < 0)
                                   return value(R::traceRadiance(scene, get(c, 0), get(c, 4)));
                               dvec3 r = glm::reflect(d, hit.n);
                               dvec3 e = hitError(vec3(hit.p), vec3(hit.n), scene.spheres[hit.sphere].radius);
                               double alongN = glm::dot(glm::abs(hit.n), e), alongR = glm::dot(glm::abs(r), e);
                               if (glm::length(alongR * r - alongN * hit.n) <= 0.25 * alongN)
                                   return value(R::traceRadiance(scene, get(c, 0), get(c, 4)));
                               return value(dvec3(-2.0));
                           }});
    tr.mistakes.push_back(
        {"rays caught between mirrors end in the background colour (the background added after the last bounce)",
         "a path that ends after maxBounces() bounces ends with nothing: the background counts only for a ray that "
         "misses every sphere, not after the last bounce",
         [scene](const ProbeCase& c) { return value(traceVariant(scene, get(c, 0), get(c, 4), true, false, true)); }});
    tr.groupHints = {{"metal sphere (bounces)", "check the bounce: origin offset, reflect(dir, n), throughput"},
                     {"between two facing mirrors",
                      "stop after the primary hit and maxBounces() bounces, and add the background only for a ray "
                      "that misses every sphere, never after the last bounce"}};
    return {fr, tr};
}

}  // namespace

RL_UNIT_PROBES { return reflectionProbes(); }

}  // namespace rl
