// The probes of exercise 04-shadows: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// The exercise's offset in double: p + dot(|n|, e) n.
dvec3 offsetOrigin(dvec3 p, dvec3 n, dvec3 e) { return p + glm::dot(glm::abs(n), e) * n; }

// Inputs of the visibility probe (shaders/probe.glsl): a p, b n, c light,
// d.xyz Hit.error, d.w Hit.sphere (what the shader gets); in[16] the sphere p
// truly lies on (for the expected value only).
constexpr int kTrueSphere = 16;

// The geometric truth (reference-model.md): is the segment from the exact
// surface point to the light free of spheres? p is taken back onto its sphere
// in double; a sphere is convex, so its own sphere blocks the light only past
// its far root -2 (p - c).l when the segment goes into it.
bool visibleInTruth(const Scene& scene, int own, dvec3 p, dvec3 light) {
    const Sphere& home = scene.spheres[own];
    p = home.center + home.radius * glm::normalize(p - home.center);
    dvec3 toLight = light - p;
    double distance = glm::length(toLight);
    if (distance == 0.0) return true;
    dvec3 l = toLight / distance;
    for (int j = 0; j < int(scene.spheres.size()); ++j) {
        double t = j == own ? -2.0 * glm::dot(p - home.center, l)
                            : R::intersectSphere(p, l, scene.spheres[j].center, scene.spheres[j].radius);
        if (t > 0.0 && t < distance) return false;
    }
    return true;
}

// Visibility as a student's mistaken shadow ray sees it, in double from the
// point p as the shader has it: `origin` where the ray starts, tMax where it
// stops, the sphere it starts on skipped only when `leaving` is a sphere.
double mistakenVisibility(const Scene& scene, const ProbeCase& c, dvec3 origin, double shorten) {
    dvec3 toLight = get(c, 8) - origin;
    double distance = glm::length(toLight);
    dvec3 l = toLight / distance;
    int leaving = int(f(c, 15));
    for (int j = 0; j < int(scene.spheres.size()); ++j) {
        const Sphere& s = scene.spheres[j];
        double t;
        if (j == leaving) {
            double b = glm::dot(origin - s.center, l);
            t = b >= 0 ? -1.0 : -2.0 * b;
        } else {
            t = R::intersectSphere(origin, l, s.center, s.radius);
        }
        if (t > 0.0 && t < distance - shorten) return 0.0;
    }
    return 1.0;
}

std::vector<ProbeSpec> shadowProbes() {
    ProbeSpec o{"offsetRayOrigin", "offsetRayOrigin(p, n, pError)", 3};
    Random rng(404);
    for (double scale : {1e-3, 1.0, 1e3, 1e5}) {
        for (int k = 0; k < 10; ++k) {
            ProbeCase c;
            vec3 p = float(scale) * rng.point(dvec3(-1), dvec3(1));
            vec3 n = rng.unitVector();
            put(c, 0, p);
            put(c, 4, n);
            put(c, 8, hitError(p, n, scale * rng.range(1, 3)));  // a sphere of the scene's size
            c.group = scale == 1e-3 ? "tiny scene (1e-3)"
                      : scale == 1 ? "unit scene" : scale == 1e3 ? "large scene (1e3)" : "huge scene (1e5)";
            o.cases.push_back(c);
        }
    }
    // Small spheres far from the origin (|p| >> r, issue #23): pError follows
    // |p| component by component, not the radius, and is far from parallel
    // to n. The centre lies along one axis at 1e2 to 1e6 and n mostly across
    // it: the extent along n is about gamma_12 r, while |pError| and its
    // largest component are gamma_12 |p|, 1e2 to 1e9 times more.
    Random farRng(4040);  // its own draws: the cases after these stay as they were
    for (int k = 0; k < 12; ++k) {
        ProbeCase c;
        int axis = k % 3;
        double radius = std::pow(10.0, farRng.range(-3, 0)), distance = std::pow(10.0, farRng.range(2, 6));
        dvec3 centre(0.0);
        centre[axis] = (k % 2 ? -1 : 1) * distance;
        dvec3 n = dvec3(farRng.unitVector());
        n[axis] *= 1e-3;  // across the axis: p's large component is not n's
        n = glm::normalize(n);
        vec3 p = vec3(centre + radius * n);
        put(c, 0, p);
        put(c, 4, vec3(n));
        put(c, 8, hitError(p, vec3(n), radius));
        c.group = "small sphere far from the origin";
        o.cases.push_back(c);
    }
    o.expected = [](const ProbeCase& c) { return value(offsetOrigin(get(c, 0), get(c, 4), get(c, 8))); };
    // The offset d = dot(|n|, e) >= gamma_12 r > 12 u max|p| (r >= |p| above);
    // p_i + d n_i rounds by at most u |p_i| more. A quarter of d plus 2 u max|p|
    // (at most 0.42 d) keeps a right answer and rejects a missing offset, an
    // offset off the normal (>= d / sqrt(3) in some component) or a fixed one.
    o.tolerance = [](const ProbeCase& c) {
        dvec3 p = get(c, 0);
        double d = glm::dot(glm::abs(get(c, 4)), get(c, 8));
        return std::make_pair(0.25 * d + 2 * kUnitRoundoff * std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))), 0.0);
    };
    o.describe = [](const ProbeCase& c) {
        return "p=" + fmt(get(c, 0)) + " n=" + fmt(get(c, 4)) + " pError=" + fmt(get(c, 8));
    };
    const std::string formula = "origin = p + dot(abs(n), pError) * n";
    o.mistakes = {
        {"shadow acne: rays start exactly on the surface", "push the origin along n past the error bound: " + formula,
         [](const ProbeCase& c) { return value(get(c, 0)); }},
        {"the origin is pushed along the error vector, not along the normal",
         "the offset goes along n; its length is the error bound's extent along n: " + formula,
         [](const ProbeCase& c) { return value(get(c, 0) + get(c, 8)); }},
        {"the origin is pushed into the surface", "n faces the side the ray leaves to: add the offset, " + formula,
         [](const ProbeCase& c) { return value(get(c, 0) - glm::dot(glm::abs(get(c, 4)), get(c, 8)) * get(c, 4)); }},
    };
    o.mistakes.push_back({"the offset's length is |pError|, not its extent along n: on a small sphere far from the "
                          "origin pError follows |p|, and rays start far off the surface (light leaks, lost contact "
                          "shadows)",
                          "the length is the bound's extent along n, dot(abs(n), pError): " + formula,
                          [](const ProbeCase& c) { return value(get(c, 0) + glm::length(get(c, 8)) * get(c, 4)); }});
    o.mistakes.push_back({"the offset's length is the largest component of pError, not its extent along n: on a small "
                          "sphere far from the origin that is |p|'s rounding, not the radius's",
                          "the length is the bound's extent along n, dot(abs(n), pError): " + formula,
                          [](const ProbeCase& c) {
                              dvec3 e = get(c, 8);
                              return value(get(c, 0) + std::max(e.x, std::max(e.y, e.z)) * get(c, 4));
                          }});
    for (double epsilon : {1e-2, 1e-3, 1e-4, 1e-5})  // the usual fixed epsilons
        o.mistakes.push_back({"a fixed offset of " + fmt(epsilon) + ": too large for a tiny scene (light leaks), too small "
                              "for a huge one (acne)",
                              "the offset follows the hit point's error bound, not a constant: " + formula,
                              [epsilon](const ProbeCase& c) { return value(get(c, 0) + epsilon * get(c, 4)); }});
    o.groupHints = {{"tiny scene (1e-3)", "a fixed epsilon is too large for a tiny scene: use the error bound pError"},
                    {"huge scene (1e5)", "a fixed epsilon is too small for a huge scene: use the error bound pError"},
                    {"small sphere far from the origin",
                     "pError follows |p| here, not the radius: the offset is its extent along n, dot(abs(n), pError)"}};

    ProbeSpec v{"lightVisibility", "lightVisibility(hit, lightPosition)", 1};
    v.needsScene = true;
    Scene scene = probeScene();
    // A probe hit: p on sphere `own` (or pushed `depth` into it, as far as
    // its error bound allows), Hit.sphere = `leaving`.
    auto addHit = [&](int own, dvec3 outward, dvec3 light, int leaving, double depth, const std::string& group) {
        const Sphere& sp = scene.spheres[own];
        dvec3 n = glm::normalize(outward);
        vec3 p = vec3(sp.center + sp.radius * n);
        vec3 e = hitError(p, vec3(n), sp.radius);
        p = vec3(dvec3(p) - depth * glm::dot(glm::abs(n), dvec3(e)) * n);
        ProbeCase c;
        put(c, 0, p);
        put(c, 4, vec3(n));
        put(c, 8, vec3(light));
        put(c, 12, e);
        c.in[15] = float(leaving);
        c.in[kTrueSphere] = float(own);
        c.group = group;
        v.cases.push_back(c);
    };
    for (int k = 0; k < 60; ++k) {  // camera rays onto the scene, lit by one light or the other
        double y = rng.range(2, 5), x = rng.range(-4, 4);
        dvec3 origin(x, y, 8);
        dvec3 target = rng.dpoint(dvec3(-3, 0, -1), dvec3(3, 1.5, 1));
        R::Hit hit;
        if (!R::closestHit(scene, origin, glm::normalize(target - origin), hit)) continue;
        dvec3 outward = hit.p - scene.spheres[hit.sphere].center;
        dvec3 light = k % 2 ? scene.lights[0].position : scene.lights[1].position;
        // The framework asks only for lights in front of the surface (NoL > 0, lighting.glsl).
        if (glm::dot(light - hit.p, outward) <= 0.0) continue;
        addHit(hit.sphere, outward, light, hit.sphere, 0.0, "scene point");
    }
    for (int k = 0; k < 8; ++k) {  // ground right beside the red sphere's contact point, light straight above: shadow
        double a = rng.range(0, 2 * R::kPi), d = rng.range(0.1, 0.6);
        addHit(0, dvec3(d * std::cos(a), 100, d * std::sin(a)), {0, 6, 0}, 0, 0.0, "under an occluder");
    }
    for (int k = 0; k < 8; ++k) {  // red sphere facing the gold one, the light in between: lit
        dvec3 towards = glm::normalize(scene.spheres[2].center - scene.spheres[1].center + 0.1 * dvec3(rng.unitVector()));
        dvec3 p = scene.spheres[1].center + scene.spheres[1].radius * towards;
        double t = R::intersectSphere(p, towards, scene.spheres[2].center, scene.spheres[2].radius);
        if (t > 0) addHit(1, towards, p + rng.range(0.2, 0.8) * t * towards, 1, 0.0, "occluder beyond the light");
    }
    // Grazing light over the ground (radius 100), nothing in the way, p as far
    // inside the ground as its error bound allows, and Hit.sphere = NO_SPHERE:
    // only a push along n gets the ray out (one along l stays inside).
    for (int k = 0; k < 12; ++k) {
        double z = rng.range(-1.5, 1.5), x = rng.range(5, 7);
        dvec3 outward(x, 100, z);
        dvec3 n = glm::normalize(outward);
        dvec3 l = glm::normalize(dvec3(rng.around(vec3(n), rng.range(0.002, 0.02))));
        dvec3 p = scene.spheres[0].center + 100.0 * n;
        addHit(0, outward, p + rng.range(0.5, 2.0) * l, -1, 0.9, "grazing light on a large ground");
    }
    // The cluster scaled by 1e-3 (spheres 6 and 7, after the two mirrors):
    // the light sits just inside the occluder, 2e-5 to 8e-4 past its near
    // side: a shadow ray shortened by a fixed 1e-3 (or 1e-4) before the light
    // misses the occluder.
    for (double gap : {2e-5, 2e-4, 8e-4})
        for (int k = 0; k < 3; ++k) {
            const Sphere& receiver = scene.spheres[6];
            const Sphere& occluder = scene.spheres[7];
            double z = rng.range(-1, 1), x = rng.range(-1, 1);
            dvec3 outward = dvec3(0, 1, 0) + 0.2 * dvec3(x, 0, z);
            dvec3 p = receiver.center + receiver.radius * glm::normalize(outward);
            dvec3 l = glm::normalize(occluder.center - p);
            double entry = R::intersectSphere(p, l, occluder.center, occluder.radius);
            addHit(6, outward, p + (entry + gap) * l, 6, 0.0, "light next to an occluder (scene scaled by 1e-3)");
        }
    v.expected = [scene](const ProbeCase& c) {
        return value(visibleInTruth(scene, int(f(c, kTrueSphere)), get(c, 0), get(c, 8)) ? 1.0 : 0.0);
    };
    v.tolerance = [](const ProbeCase&) { return std::make_pair(1e-6, 0.0); };  // 0 or 1 exactly
    v.describe = [](const ProbeCase& c) {
        return "p=" + fmt(get(c, 0)) + " n=" + fmt(get(c, 4)) + " light=" + fmt(get(c, 8)) + " error=" + fmt(get(c, 12)) +
               " sphere=" + fmt(f(c, 15));
    };
    auto origin = [](const ProbeCase& c) { return offsetOrigin(get(c, 0), get(c, 4), get(c, 12)); };
    v.mistakes = {
        {"spheres beyond the light cast shadows", "only occluders with t < distance to the light count",
         [scene, origin](const ProbeCase& c) { return value(mistakenVisibility(scene, c, origin(c), -1e30)); }},
        {"shadow acne under grazing light: the shadow ray starts along l, not along n",
         "start at offsetRayOrigin(hit.p, hit.n, hit.error): along the normal, whatever the ray's direction",
         [scene](const ProbeCase& c) {
             dvec3 p = get(c, 0), l = glm::normalize(get(c, 8) - p);
             return value(mistakenVisibility(scene, c, p + glm::dot(glm::abs(get(c, 4)), get(c, 12)) * l, 0.0));
         }},
        {"shadow acne: the shadow ray starts at hit.p", "start the shadow ray at offsetRayOrigin(hit.p, hit.n, hit.error)",
         [scene](const ProbeCase& c) { return value(mistakenVisibility(scene, c, get(c, 0), 0.0)); }},
    };
    for (double epsilon : {1e-3, 1e-4})
        v.mistakes.push_back({"lights next to an occluder shine through it: the shadow ray stops " + fmt(epsilon) +
                                  " before the light",
                              "tMax is the distance to the light itself: a fixed margin is the whole scene at scale 1e-3",
                              [scene, origin, epsilon](const ProbeCase& c) {
                                  return value(mistakenVisibility(scene, c, origin(c), epsilon));
                              }});
    v.groupHints = {{"occluder beyond the light", "stop the shadow ray at the light: tMax = distance to the light"},
                    {"grazing light on a large ground", "offset along hit.n (offsetRayOrigin), not along the light direction"},
                    {"light next to an occluder (scene scaled by 1e-3)",
                     "do not shorten the shadow ray: tMax = distance to the light"},
                    {"scene point", "start the shadow ray at offsetRayOrigin(hit.p, hit.n, hit.error), not at hit.p"}};
    return {o, v};
}

}  // namespace

RL_UNIT_PROBES { return shadowProbes(); }

}  // namespace rl
