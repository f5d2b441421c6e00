// The probes of exercise 02-intersect: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 02 intersection ----------------------------------------------------------------------

std::vector<ProbeSpec> intersectProbes() {
    ProbeSpec p{"intersectSphere", "intersectSphere(origin, dir, center, radius)", 1};
    Random rng(202);
    auto add = [&](vec3 origin, vec3 dir, vec3 center, float radius, const std::string& group) {
        ProbeCase c;
        put(c, 0, origin);
        put(c, 4, glm::normalize(dir));
        put(c, 8, center);
        c.in[11] = radius;
        c.group = group;
        p.cases.push_back(c);
    };
    for (int k = 0; k < 40; ++k) {  // ordinary: a sphere in front, hit or missed
        vec3 center = rng.point(dvec3(-3, -3, -8), dvec3(3, 3, -2));
        float r = float(rng.range(0.2, 1.5));
        vec3 towards = rng.unitVector();
        vec3 aim = center + float(rng.range(-1.4, 1.4)) * r * towards;
        vec3 origin(float(rng.range(-1, 1)), 0, 0);
        add(origin, aim, center, r, "sphere in front");
    }
    for (float distance : {1e3f, 3e3f, 1e4f})  // the textbook b^2 - c cancels here
        for (int k = 0; k < 8; ++k) {
            vec3 dir = rng.unitVector();
            vec3 side = glm::normalize(glm::cross(dir, rng.unitVector()));
            add(vec3(0), dir + float(rng.range(0, 0.7) / distance) * side, distance * dir, 1.0f,
                "far sphere (distance 1e3 to 1e4)");
        }
    for (int k = 0; k < 10; ++k) {  // origin inside: the far root
        vec3 center = rng.point(dvec3(-2), dvec3(2));
        float r = float(rng.range(1, 3));
        vec3 dir = rng.unitVector();
        vec3 towards = rng.unitVector();
        add(center + float(rng.range(0, 0.8)) * r * towards, dir, center, r, "origin inside the sphere");
    }
    for (int k = 0; k < 6; ++k) {  // from the very centre b = 0: GLSL's sign(0) is 0
        vec3 center = rng.point(dvec3(-2), dvec3(2));
        float r = float(rng.range(0.5, 3));
        add(center, rng.unitVector(), center, r, "origin at the centre");
    }
    for (int k = 0; k < 10; ++k) {  // behind the origin: a miss
        vec3 dir = rng.unitVector();
        float r = float(rng.range(0.3, 1));
        vec3 jitter = rng.unitVector();
        add(vec3(0), dir, -float(rng.range(3, 10)) * dir + 0.1f * jitter, r, "sphere behind the origin");
    }
    for (int k = 0; k < 10; ++k) {  // nearly tangent: just inside (hit) or just outside (miss)
        vec3 dir = rng.unitVector();
        vec3 side = glm::normalize(glm::cross(dir, rng.unitVector()));
        float r = float(rng.range(0.5, 2));
        float d = r * (k % 2 ? 1.001f : 0.999f);  // 1e-3 of r from tangency: far beyond float32 error
        add(vec3(0), dir, 5.0f * dir + d * side, r, "nearly tangent ray");
    }
    for (float scale : {1e-3f, 1e3f})  // tiny and huge spheres
        for (int k = 0; k < 6; ++k) {
            double y = rng.range(-1, 1), x = rng.range(-1, 1);
            vec3 center = scale * vec3(float(x), float(y), -4);
            add(vec3(0), center + scale * 0.3f * rng.unitVector(), center, 0.5f * scale,
                scale < 1 ? "tiny sphere (1e-3)" : "large sphere (1e3)");
        }
    // Rays that start exactly on a surface, just inside it, or graze it.
    // On the surface and tangent: axis-aligned, centres on a grid of 1/4 and
    // radii that are powers of two, so that float32 computes f = origin -
    // centre, c = |f|^2 - r^2 = 0, the zero discriminant and sqrt(r^2)
    // exactly: every correct form (the stable one, the geometric one) gets
    // the exact answer there, and `t >= 0` or `discriminant <= 0` shows at
    // once. Just inside: 1e-5 to 1e-3 of r inside, 10 or more float32 ulps
    // of the coordinates (|centre| + r <= 4), so that the origin is inside in float32 too;
    // within 60 degrees of the radial direction, so that no correct form
    // cancels. There the far root is 2 |b| from a near root of ~0: a far root
    // computed from c / (-b - sqrt(discriminant)) (the cancelling root first)
    // is off by percents.
    Random edge(2020);
    const float radii[] = {0.5f, 1.0f, 2.0f, 0.25f, 4.0f, 1.0f};
    const vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    auto gridPoint = [&]() {  // multiples of 1/4 in [-2, 2]: exact sums with the radii above
        return 0.25f * glm::floor(edge.point(dvec3(-8), dvec3(9)));
    };
    for (int k = 0; k < 12; ++k) {  // on the surface, going in (the far root) or out (NO_HIT)
        vec3 center = gridPoint(), axis = axes[(k / 2) % 6];
        float r = radii[k % 6];
        add(center + r * axis, k % 2 ? axis : -axis, center, r, "origin on or just inside the surface");
    }
    for (int k = 0; k < 8; ++k) {  // just inside, going inwards (the far root) or outwards (a root near 0)
        vec3 center = gridPoint(), u = edge.unitVector();
        float r = float(edge.range(0.5, 2));
        const double inside[] = {1e-5, 1e-4, 1e-3};
        vec3 origin = center + float(r * (1 - inside[k % 3])) * u;
        add(origin, edge.around(k % 2 ? u : -u, edge.range(0.5, 1)), center, r, "origin on or just inside the surface");
    }
    for (int k = 0; k < 8; ++k) {  // exactly tangent: the discriminant is 0, the hit at t = s
        vec3 center = gridPoint(), a = axes[k % 6], b = axes[(k + 1) % 6];
        float r = radii[k % 6], s = float(2 + k % 4);
        add(center + r * a - s * b, b, center, r, "exactly tangent ray (discriminant 0)");
    }
    // The ray's origin and the sphere both far from (0, 0, 0), a few radii
    // apart: f = origin - center is exact in float32 there (Sterbenz), so
    // every form built on f is as good as near the origin, but c written
    // out as |origin|^2 - 2 origin.center + |center|^2 - r^2 loses the
    // ~1e8 it cancels to rounding of ~10 (issue 35: it passed every other
    // case and changed pixels only for a far camera).
    Random far(2035);
    for (int k = 0; k < 8; ++k) {
        const float distance = float(far.range(5e3, 2e4));
        const vec3 base = distance * far.unitVector();
        const vec3 towards = far.unitVector();
        const float r = float(far.range(0.5, 1.5));
        const float gap = float(far.range(3, 8));
        const vec3 center = base + gap * towards;
        const float miss = float(far.range(-0.8, 0.8));
        const vec3 aim = center + miss * r * far.unitVector() - base;
        add(base, aim, center, r, "origin and sphere far from (0, 0, 0) (1e4)");
    }
    p.expected = [](const ProbeCase& c) { return value(R::intersectSphere(get(c, 0), get(c, 4), get(c, 8), f(c, 11))); };
    // t is computed from origin - center, which float32 rounds to ~1 ulp of
    // the larger of |origin| and |center| + radius; 1e-5 of that scale is
    // ~100 ulps. A miss must be a miss (NO_HIT = -1 exactly).
    p.tolerance = [](const ProbeCase& c) {
        double scale = std::max(glm::length(get(c, 0)), glm::length(get(c, 8)) + f(c, 11));
        return std::make_pair(1e-5 * scale, 0.0);
    };
    p.describe = [](const ProbeCase& c) {
        return "origin=" + fmt(get(c, 0)) + " dir=" + fmt(get(c, 4)) + " center=" + fmt(get(c, 8)) +
               " r=" + fmt(f(c, 11));
    };
    // The two roots of the quadratic in double, nearest first (either may be
    // negative; 0 when the origin is on the surface): the stable form, so
    // that c = 0 gives a root of exactly 0 as in float32.
    auto roots = [](const ProbeCase& c, double& t0, double& t1) {
        dvec3 o = get(c, 0), d = get(c, 4), ce = get(c, 8);
        double r = f(c, 11), b = glm::dot(o - ce, d);
        double disc = r * r - glm::length2(o - ce - b * d);
        if (disc < 0) return false;
        double q = -b - (b >= 0 ? 1.0 : -1.0) * std::sqrt(disc);
        if (q == 0) return false;
        t0 = (glm::length2(o - ce) - r * r) / q;
        t1 = q;
        if (t0 > t1) std::swap(t0, t1);
        return true;
    };
    // A mistake in choosing among the roots: `pick` gets them nearest first.
    auto choosing = [=](double (*pick)(double, double)) {
        return [=](const ProbeCase& c) {
            double t0, t1;
            return value(roots(c, t0, t1) ? pick(t0, t1) : R::kNoHit);
        };
    };
    p.mistakes = {
        {"spheres behind the camera are hit (negative t accepted)",
         "only roots with t > 0 count; a sphere entirely behind the origin is NO_HIT",
         choosing([](double t0, double t1) { return t0 > 0 ? t0 : t1 > 0 ? t1 : t0; })},
        {"from inside a sphere the hit is behind the origin (the near root was taken)",
         "when the origin is inside, the near root is negative: return the far root",
         choosing([](double t0, double t1) { return t1 > 0 ? t0 : R::kNoHit; })},
        {"spheres behind the camera appear and those in front vanish (the roots have the wrong sign)",
         "the quadratic's roots come from -b: q = -b - sign(b) sqrt(discriminant)",
         choosing([](double t0, double t1) { return -t1 > 0 ? -t1 : -t0 > 0 ? -t0 : R::kNoHit; })},
        {"the back of each sphere is seen through its front (the far root comes first)",
         "take the NEAR root when it is positive; the far one only from inside",
         choosing([](double t0, double t1) { return t1 > 0 ? t1 : t0 > 0 ? t0 : R::kNoHit; })},
        {"a ray that starts on a surface hits it at t = 0 (t >= 0 instead of t > 0)",
         "only t > 0 counts: the root t = 0 is the ray's own origin",
         choosing([](double t0, double t1) { return t0 >= 0 ? t0 : t1 >= 0 ? t1 : R::kNoHit; })},
        {"a ray that just touches a sphere misses it (a zero discriminant taken for a miss)",
         "only a negative discriminant is a miss: discriminant < 0.0, not <= 0.0",
         [=](const ProbeCase& c) {
             dvec3 o = get(c, 0), d = get(c, 4), ce = get(c, 8);
             double r = f(c, 11), b = glm::dot(o - ce, d);
             if (r * r - glm::length2(o - ce - b * d) <= 0) return value(R::kNoHit);
             return value(R::intersectSphere(o, d, ce, r));
         }},
    };
    // A t-min epsilon (t0 > 1e-4): the usual habit against self-hits, which
    // the framework's offset (exercise 04) and its exact handling of the
    // sphere a ray leaves make unnecessary. Its symptom is not noise: roots
    // nearer than the epsilon are dropped, so a ray from just off a surface
    // passes through it and spheres nearer than it vanish.
    // (1e-5 and below change no probe case: such an epsilon passes.)
    for (double epsilon : {1e-2, 1e-3, 1e-4}) {
        auto threshold = [=](const ProbeCase& c) {
            double t0, t1;
            if (!roots(c, t0, t1)) return value(R::kNoHit);
            return value(t0 > epsilon ? t0 : t1 > epsilon ? t1 : R::kNoHit);
        };
        p.mistakes.push_back({"roots nearer than " + fmt(epsilon) + " are dropped (a t-min epsilon): a ray from just "
                              "off a surface passes through it, and spheres nearer than that vanish",
                              "only t > 0 counts, with no epsilon: the framework keeps secondary rays off their "
                              "surface (exercise 04's offset, the sphere a ray leaves handled exactly)",
                              threshold});
    }
    p.groupHints = {
        {"origin at the centre", "from the centre b = 0, where GLSL's sign(0.0) is 0 (so q = 0) and b / abs(b) is "
                                 "0 / 0 = NaN: pick the sign with b >= 0.0 ? 1.0 : -1.0"},
        {"far sphere (distance 1e3 to 1e4)", "b^2 - c cancels in float32 for far spheres: use the discriminant "
                                              "r^2 - |f - b dir|^2 (perpendicular distance) and the roots c/q, q"},
        {"origin and sphere far from (0, 0, 0) (1e4)",
         "far from (0, 0, 0), c written out as |origin|^2 - 2 origin.center + |center|^2 - r^2 cancels in float32: "
         "compute f = origin - center first and c = dot(f, f) - r^2"},
        {"origin inside the sphere", "from inside, the near root is behind the origin: take the far one"},
        {"sphere behind the origin", "both roots negative means NO_HIT"},
        {"nearly tangent ray", "a negative discriminant is a miss; zero or positive is a hit"},
        {"exactly tangent ray (discriminant 0)", "a negative discriminant is a miss; zero or positive is a hit"},
        {"origin on or just inside the surface",
         "one root is at or near t = 0 here and must be returned whenever it is > 0, however small (no t-min "
         "epsilon); that root must come from c / q with q = -b - sign(b) sqrt(discriminant), where -b +/- "
         "sqrt(discriminant) would cancel"},
    };
    return {p};
}

}  // namespace

RL_UNIT_PROBES { return intersectProbes(); }

}  // namespace rl
