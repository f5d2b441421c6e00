#include "checks/probe_cases.h"

#include "reference/cpu_reference.h"

#include <glm/geometric.hpp>
#include <glm/gtx/norm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace rl {
namespace {

using glm::dvec3;
using glm::vec3;
namespace R = ref;

// ---- inputs ---------------------------------------------------------------------

// splitmix64: a tiny generator with the same sequence on every platform, so
// every student and every run sees the same cases. Every draw is sequenced:
// one draw per statement or per declarator, never two in the arguments of
// one call or the operands of one operator, whose order C++ leaves to the
// compiler (g++ and clang++ differed on 8 of the 10 exercises). Where
// several values come from one statement, the draws run in the order g++
// happened to use when the cases were made (often the last argument
// first), so the cases are those every check and hint was tuned on; the
// hash in tests/unit/test_probe_cases.cpp pins them.
struct Random {
    std::uint64_t state;
    explicit Random(std::uint64_t seed) : state(seed) {}
    double uniform() {  // [0, 1)
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    vec3 unitVector() {
        double z = range(-1, 1), phi = range(0, 2 * R::kPi), s = std::sqrt(1 - z * z);
        return glm::normalize(vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
    }
    // A unit vector at angle acos(cosTheta) from n.
    vec3 around(vec3 n, double cosTheta) {
        vec3 t = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0)));
        vec3 b = glm::cross(n, t);
        double s = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), phi = range(0, 2 * R::kPi);
        return glm::normalize(float(cosTheta) * n + float(s * std::cos(phi)) * t + float(s * std::sin(phi)) * b);
    }
    vec3 colour() {
        double b = uniform(), g = uniform(), r = uniform();
        return vec3(float(r), float(g), float(b));
    }
    // A point of the box [lo, hi], z drawn first, then y, then x.
    dvec3 dpoint(dvec3 lo, dvec3 hi) {
        double z = range(lo.z, hi.z), y = range(lo.y, hi.y), x = range(lo.x, hi.x);
        return dvec3(x, y, z);
    }
    vec3 point(dvec3 lo, dvec3 hi) { return vec3(dpoint(lo, hi)); }
};

void put(ProbeCase& c, int at, vec3 v) {
    c.in[at] = v.x;
    c.in[at + 1] = v.y;
    c.in[at + 2] = v.z;
}
dvec3 get(const ProbeCase& c, int at) { return dvec3(c.in[at], c.in[at + 1], c.in[at + 2]); }
double f(const ProbeCase& c, int at) { return c.in[at]; }
ProbeValue value(dvec3 v) { return {v.x, v.y, v.z}; }
ProbeValue value(double x) { return {x, 0, 0}; }

std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return b;
}
std::string fmt(dvec3 v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")"; }

Material materialAt(const ProbeCase& c) {
    Material m;
    m.albedo = get(c, 0);
    m.roughness = f(c, 3);
    m.metallic = f(c, 4);
    m.ao = f(c, 5);
    return m;
}

// Tolerances, against what GLSL ES 3.00 guarantees for highp (section
// 4.5.1; desktop GLSL's bounds are the same or tighter): float32 with
// relative precision 2^-24 = 6e-8; +, -, * correctly rounded; division 2.5
// ulp; inversesqrt 2 ulp (sqrt inherited from it); exp2 and exp (3 + 2|x|)
// ulp, log2 3 ulp (absolute 2^-21 on [0.5, 2]); pow inherited from
// exp2(y log2 x), so pow(x, 5) is good to ~5 * 2^-21 * ln 2 = 1.7e-6
// relative. Each function here chains 5 to 30 such operations with condition
// numbers up to ~10: at most a few 1e-5. 1e-4 relative is above what a
// right float32 answer can be off by on any conforming implementation, and
// far below any of the mistakes. Trigonometry (undefined precision in the
// spec) enters only the camera: see cameraProbes().
constexpr double kRel = 1e-4;
constexpr double kAbs = 1e-6;  // values near zero: a few ulps of the typical magnitude 1e-2..1
auto standardTolerance = [](const ProbeCase&) { return std::make_pair(kAbs, kRel); };

// ---- 01 camera --------------------------------------------------------------------------

std::vector<ProbeSpec> cameraProbes() {
    ProbeSpec offsets{ProbeFunction::SampleOffset, "sampleOffset", "sampleOffset(s, n)", 2};
    for (int n = 1; n <= 4; ++n)
        for (int s = 0; s < n * n; ++s) {
            ProbeCase c;
            c.in[0] = float(s);
            c.in[1] = float(n);
            c.group = n == 1 ? "one sample per pixel" : "n x n samples";
            offsets.cases.push_back(c);
        }
    offsets.expected = [](const ProbeCase& c) {
        glm::dvec2 o = R::sampleOffset(int(f(c, 0)), int(f(c, 1)));
        return ProbeValue{o.x, o.y, 0};
    };
    offsets.tolerance = [](const ProbeCase&) { return std::make_pair(1e-6, 0.0); };  // (a + 0.5)/n: exact to 1 ulp
    offsets.describe = [](const ProbeCase& c) { return "s=" + fmt(f(c, 0)) + " n=" + fmt(f(c, 1)); };
    offsets.mistakes = {
        {"samples sit on the pixel corners", "the offset is the cell CENTRE: (a + 0.5)/n, not a/n",
         [](const ProbeCase& c) {
             int s = int(f(c, 0)), n = int(f(c, 1));
             return ProbeValue{double(s % n) / n, double(s / n) / n, 0};
         }},
        {"x and y of the sample grid are swapped", "a = s % n runs along x, b = s / n along y",
         [](const ProbeCase& c) {
             glm::dvec2 o = R::sampleOffset(int(f(c, 0)), int(f(c, 1)));
             return ProbeValue{o.y, o.x, 0};
         }},
    };

    ProbeSpec rays{ProbeFunction::CameraRay, "cameraRayDirection",
                   "cameraRayDirection(pixelSample, resolution, fovY, right, up, forward)", 3};
    Random rng(101);
    const glm::vec2 sizes[] = {{640, 480}, {320, 160}, {100, 300}, {1, 1}, {7, 5}};
    for (int k = 0; k < 80; ++k) {
        ProbeCase c;
        glm::vec2 res = sizes[k % 5];
        double jy = std::floor(rng.range(0, res.y)), sy = rng.uniform();
        double jx = std::floor(rng.range(0, res.x)), sx = rng.uniform();
        glm::vec2 px(float(jx + sx), float(jy + sy));
        if (k % 7 == 0) px = glm::vec2(0.5f, 0.5f);                  // bottom-left pixel centre
        if (k % 7 == 1) px = res - glm::vec2(0.5f);                   // top-right pixel centre
        float fov = float(rng.range(0.2, 2.6));
        vec3 forward = rng.unitVector();
        vec3 right = glm::normalize(glm::cross(forward, rng.unitVector()));
        vec3 up = glm::cross(right, forward);
        c.in[0] = px.x, c.in[1] = px.y, c.in[2] = res.x, c.in[3] = res.y, c.in[4] = fov;
        put(c, 8, right);
        put(c, 12, up);
        put(c, 16, forward);
        c.group = res.x == res.y ? "square image" : "non-square image (aspect != 1)";
        rays.cases.push_back(c);
    }
    rays.expected = [](const ProbeCase& c) {
        return value(R::cameraRayDirection({f(c, 0), f(c, 1)}, {f(c, 2), f(c, 3)}, f(c, 4), get(c, 8), get(c, 12),
                                           get(c, 16)));
    };
    // A unit vector: 1e-5 absolute is ~100 ulps of its components (tan and normalize, a few ulps each).
    // GLSL ES 3.00 (section 4.5.1) bounds +, -, * (correctly rounded), / (2.5
    // ulp), inversesqrt (2 ulp), exp and log, and leaves the trigonometric
    // functions' precision undefined. The least precise tan measured on a
    // conforming implementation is SwiftShader's (Chromium without a GPU):
    // 7.6e-5 relative. A relative error e in t = tan(fovY/2) scales the
    // lateral part s of the direction (x, y, 1)/|...|, which moves the unit
    // vector by e s / (1 + s^2) <= e / 2. Allowing e = 2e-4 (2.6 times
    // SwiftShader's) adds 1e-4 to the 1e-5 the float32 arithmetic needs
    // (normalize: 2 ulp of inversesqrt plus a few roundings, ~1e-6). A
    // tenth of a pixel at 640 pixels and 60 degrees (1.6e-3 rad a pixel),
    // while every mistake of the contract moves rays by a pixel or more.
    rays.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5 + 1e-4, 0.0); };
    rays.describe = [](const ProbeCase& c) {
        return "pixel=(" + fmt(f(c, 0)) + ", " + fmt(f(c, 1)) + ") res=" + fmt(f(c, 2)) + "x" + fmt(f(c, 3)) +
               " fovY=" + fmt(f(c, 4));
    };
    // The ray as the contract computes it, with switches for the typical
    // mistakes: the aspect ratio on y, the half angle or the full one (or
    // fovY converted to radians a second time), rows from the top, the pixel
    // centre's +0.5 added to a pixelSample that already holds it, and the
    // direction left unnormalised.
    struct RayMistake {
        bool aspectOnY = false;
        double angleScale = 0.5;
        bool flipY = false;
        double extraOffset = 0;
        bool normalise = true;
    };
    auto rayWith = [](const ProbeCase& c, RayMistake m) {
        double t = std::tan(f(c, 4) * m.angleScale), aspect = f(c, 2) / f(c, 3);
        double x = (2 * (f(c, 0) + m.extraOffset) / f(c, 2) - 1) * t * (m.aspectOnY ? 1.0 : aspect);
        double y = (2 * (f(c, 1) + m.extraOffset) / f(c, 3) - 1) * t * (m.aspectOnY ? aspect : 1.0);
        if (m.flipY) y = -y;
        dvec3 d = x * get(c, 8) + y * get(c, 12) + get(c, 16);
        return value(m.normalise ? glm::normalize(d) : d);
    };
    RayMistake aspectOnY, fullAngle, flipped, radiansTwice, halfPixelTwice, unnormalised;
    aspectOnY.aspectOnY = true;
    fullAngle.angleScale = 1.0;
    flipped.flipY = true;
    radiansTwice.angleScale = 0.5 * R::kPi / 180;
    halfPixelTwice.extraOffset = 0.5;
    unnormalised.normalise = false;
    rays.mistakes = {
        {"the image is squashed: the aspect ratio scales y instead of x",
         "x = (2 (i + sx)/width - 1) tan(fovY/2) * aspect; y has no aspect",
         [=](const ProbeCase& c) { return rayWith(c, aspectOnY); }},
        {"the field of view is twice too wide", "t = tan(fovY / 2): fovY is the FULL vertical angle",
         [=](const ProbeCase& c) { return rayWith(c, fullAngle); }},
        {"the picture is upside down", "row j counts from the BOTTOM: y grows with j",
         [=](const ProbeCase& c) { return rayWith(c, flipped); }},
        {"the view is a telescope: fovY converted to radians a second time",
         "fovY arrives in radians already: t = tan(fovY / 2), no radians()",
         [=](const ProbeCase& c) { return rayWith(c, radiansTwice); }},
        {"the picture is shifted by half a pixel: the pixel centre's 0.5 is added twice",
         "pixelSample already holds the sample offset (i + sx, j + sy): do not add 0.5 again",
         [=](const ProbeCase& c) { return rayWith(c, halfPixelTwice); }},
        {"the ray direction is not unit length", "return normalize(x right + y up + forward)",
         [=](const ProbeCase& c) { return rayWith(c, unnormalised); }},
    };
    rays.groupHints = {{"non-square image (aspect != 1)", "check where the aspect ratio width/height goes"}};
    return {offsets, rays};
}

// ---- 02 intersection ----------------------------------------------------------------------

std::vector<ProbeSpec> intersectProbes() {
    ProbeSpec p{ProbeFunction::Intersect, "intersectSphere", "intersectSphere(origin, dir, center, radius)", 1};
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
        {"origin at the centre", "from the centre b = 0, and GLSL's sign(0.0) is 0, so q = 0: use b >= 0 ? 1 : -1"},
        {"far sphere (distance 1e3 to 1e4)", "b^2 - c cancels in float32 for far spheres: use the discriminant "
                                              "r^2 - |f - b dir|^2 (perpendicular distance) and the roots c/q, q"},
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

// ---- 03 Lambert ------------------------------------------------------------------------

std::vector<ProbeSpec> lambertProbes() {
    ProbeSpec fd{ProbeFunction::Lambert, "Fd_Lambert", "Fd_Lambert(albedo)", 3};
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

    ProbeSpec e{ProbeFunction::Irradiance, "pointLightIrradiance",
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

// ---- 04 shadows ------------------------------------------------------------------------

// The probe scene: two spheres on a big ground, one light above, one beside.
Scene makeProbeScene() {
    Scene s;
    auto sphere = [](dvec3 c, double r, dvec3 albedo, double rough, double metal) {
        Sphere sp;
        sp.center = c;
        sp.radius = r;
        sp.material.albedo = albedo;
        sp.material.roughness = rough;
        sp.material.metallic = metal;
        return sp;
    };
    s.spheres = {sphere({0, -100, 0}, 100, {0.6, 0.6, 0.6}, 0.8, 0),
                 sphere({0, 1, 0}, 1, {0.9, 0.2, 0.1}, 0.4, 0),
                 sphere({2.5, 0.7, 0.5}, 0.7, {0.95, 0.9, 0.6}, 0.2, 1),
                 sphere({-2.2, 0.8, -0.6}, 0.8, {0.2, 0.5, 0.9}, 0.05, 0.5),
                 // Two facing mirrors off to the side: a ray between them
                 // bounces until max_bounces ends it.
                 sphere({9, 3, 0}, 1, {0.95, 0.95, 0.95}, 0.05, 1),
                 sphere({13, 3, 0}, 1, {0.9, 0.8, 0.5}, 0.05, 1),
                 // A receiver and an occluder scaled by 1e-3, in the air far
                 // from the rest: a light next to the occluder (exercise 04).
                 sphere({-6, 4, -4}, 5e-4, {0.8, 0.8, 0.8}, 0.5, 0),
                 sphere({-6, 4.0025, -4}, 5e-4, {0.8, 0.8, 0.8}, 0.5, 0)};
    Light key;
    key.position = {1, 6, 2};
    key.intensity = 60;
    Light fill;
    fill.position = {-5, 2, 4};
    fill.color = {0.6, 0.7, 1};
    fill.intensity = 25;
    s.lights = {key, fill};
    s.render.maxBounces = 3;
    s.render.ambient = 0.03;
    s.render.background = {0.2, 0.25, 0.3};
    return s;
}

// float32's unit roundoff and gamma_k, as in shaders/error_bounds.glsl.
constexpr double kUnitRoundoff = 0x1.0p-24;
double roundingGamma(double k) { return k * kUnitRoundoff / (1 - k * kUnitRoundoff); }

// Hit.error of a hit on a sphere of radius r with normal n at p, as
// closestHit() computes it (error_bounds.glsl, centre form):
// gamma_12 (|p| + r |n|).
vec3 hitError(vec3 p, vec3 n, double r) {
    dvec3 e = roundingGamma(12) * (glm::abs(dvec3(p)) + r * glm::abs(dvec3(n)));
    return vec3(e);
}

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
    ProbeSpec o{ProbeFunction::OffsetOrigin, "offsetRayOrigin", "offsetRayOrigin(p, n, pError)", 3};
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

    ProbeSpec v{ProbeFunction::Visibility, "lightVisibility", "lightVisibility(hit, lightPosition)", 1};
    v.needsScene = true;
    Scene scene = makeProbeScene();
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

// ---- 05 D -------------------------------------------------------------------------------

// n and h with n.h = cosTheta: h is n turned by theta.
void putNormalHalf(ProbeCase& c, Random& rng, double cosTheta) {
    vec3 n = rng.unitVector();
    put(c, 0, n);
    put(c, 4, cosTheta >= 1 ? n : rng.around(n, cosTheta));
}

std::vector<ProbeSpec> ggxProbes() {
    ProbeSpec d{ProbeFunction::DGgx, "D_GGX", "D_GGX(n, h, alpha)", 1};
    Random rng(505);
    for (int k = 0; k < 50; ++k) {
        ProbeCase c;
        putNormalHalf(c, rng, rng.range(0.05, 0.999));
        double r = rng.range(0.1, 1);
        c.in[8] = float(r * r);
        c.group = "random";
        d.cases.push_back(c);
    }
    for (double r : {0.045, 0.06, 0.1}) {  // the peak of a nearly mirror surface
        for (double cosTheta : {1.0, 1.0 - 1e-7, 1.0 - 1e-6, 1.0 - 4e-6}) {
            ProbeCase c;
            putNormalHalf(c, rng, cosTheta);
            c.in[8] = float(r * r);
            c.group = "near the peak, smooth surface";
            d.cases.push_back(c);
        }
    }
    for (int k = 0; k < 10; ++k) {
        ProbeCase c;
        putNormalHalf(c, rng, rng.range(0.01, 1));
        c.in[8] = 1.0f;
        c.group = "roughness 1";
        d.cases.push_back(c);
    }
    for (float alpha : {1.0f, 0.75f, 0.5f, 0.25f}) {  // the peak, n = h along an axis: every form computes it exactly
        ProbeCase c;
        put(c, 0, vec3(0, 0, 1));
        put(c, 4, vec3(0, 0, 1));
        c.in[8] = alpha;
        c.group = "peak with n = h exactly";
        d.cases.push_back(c);
    }
    d.expected = [](const ProbeCase& c) { return value(R::D_GGX(get(c, 0), get(c, 4), f(c, 8))); };
    // Near the peak the float32 inputs are themselves exact; a cancellation-free
    // form stays within 1e-3, the textbook 1 - (n.h)^2 loses several percent:
    // 1% is the budget for the peak. Elsewhere the cross-product form
    // is a handful of roundings (~1e-6); a form that computes 1 - (n.h)^2
    // loses up to ~1e-4 at n.h = 0.999, alpha = 0.01 (6e-8 absolute against
    // a denominator of 2e-3, doubled by the square): 2e-4 keeps the random
    // cases above that, and catches pi written as 3.14 (5.1e-4). With
    // alpha = 1, D = 1/pi whatever n.h, but the cross and dot products of
    // unit vectors add ~4e-7 to a denominator of 1, doubled by the square:
    // 1e-5. At the peak with n = h = (0, 0, 1) and alpha^2 exact in float32,
    // D = 1 / (pi alpha^2) is a constant, two products and a division, each
    // correctly rounded or within 2.5 ulp: at most ~4 ulp = 2.4e-7, and 1e-6
    // catches even pi written as 3.1416 (2.3e-6).
    d.tolerance = [](const ProbeCase& c) {
        if (c.group.rfind("near the peak", 0) == 0) return std::make_pair(kAbs, 1e-2);
        if (c.group == "peak with n = h exactly") return std::make_pair(0.0, 1e-6);  // D >= 1/pi here
        return std::make_pair(kAbs, c.group == "roughness 1" ? 1e-5 : 2e-4);
    };
    d.describe = [](const ProbeCase& c) {
        double NoH = glm::dot(get(c, 0), get(c, 4));
        // Near the peak n.h prints as 1: show how far from 1 it is instead.
        std::string angle = NoH > 0.999 ? "1-n.h=" + fmt(1.0 - NoH) : "n.h=" + fmt(NoH);
        return angle + " alpha=" + fmt(f(c, 8));
    };
    // D with the pi or the square of alpha missing. The denominator as
    // |n x h|^2 + (n.h)^2 alpha^2, like the reference: the float32 inputs are
    // unit vectors only to ~1e-7, which (n.h)^2 (alpha^2 - 1) + 1 turns into
    // percents near the peak, even in double.
    auto dTextbookLike = [](const ProbeCase& c, double piFactor, bool alphaSquared) {
        dvec3 n = get(c, 0), h = get(c, 4);
        double NoH = glm::dot(n, h), a = f(c, 8);
        double a2 = alphaSquared ? a * a : a;
        double den = glm::length2(glm::cross(n, h)) + NoH * NoH * a2;
        return value(a2 / (piFactor * den * den));
    };
    d.mistakes = {
        {"highlights pi times too bright", "D = alpha^2 / (pi (...)^2): the pi is missing",
         [=](const ProbeCase& c) { return dTextbookLike(c, 1.0, true); }},
        {"highlights too wide and too dim (alpha used where alpha^2 belongs)",
         "alpha is already roughness^2; the formula squares it again: alpha^2",
         [=](const ProbeCase& c) { return dTextbookLike(c, R::kPi, false); }},
    };
    d.groupHints = {{"near the peak, smooth surface",
                     "1 - (n.h)^2 cancels in float32 near n.h = 1: write it as |cross(n, h)|^2"}};
    return {d};
}

// ---- 06 G -------------------------------------------------------------------------------

std::vector<ProbeSpec> geometryProbes() {
    ProbeSpec g1{ProbeFunction::G1, "G1_SchlickGGX", "G1_SchlickGGX(NoX, k)", 1};
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

    ProbeSpec g{ProbeFunction::G, "G_SchlickGGX", "G_SchlickGGX(NoV, NoL, roughness)", 1};
    for (int k = 0; k < 50; ++k) {
        ProbeCase c;
        c.in[0] = float(rng.range(1e-4, 1));
        c.in[1] = float(rng.range(1e-3, 1));
        c.in[2] = float(k < 5 ? 0.0 : k < 10 ? 1.0 : rng.range(0, 1));
        c.group = k < 5 ? "roughness 0 (clamped to 0.045)" : k < 10 ? "roughness 1" : "random";
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
             double r = std::clamp(double(f(c, 2)), 0.045, 1.0);
             return gWithK(c, r * r / 2);
         }},
        {"roughness is not clamped", "r = clamp(roughness, 0.045, 1) before k = (r + 1)^2 / 8",
         [=](const ProbeCase& c) {
             double r = f(c, 2);
             return gWithK(c, (r + 1) * (r + 1) / 8);
         }},
        {"G is a sum, not a product", "G = G1(NoV) * G1(NoL)",
         [](const ProbeCase& c) {
             double r = std::clamp(double(f(c, 2)), 0.045, 1.0), k = (r + 1) * (r + 1) / 8;
             return value(R::G1_SchlickGGX(f(c, 0), k) + R::G1_SchlickGGX(f(c, 1), k));
         }},
    };
    g.groupHints = {{"roughness 0 (clamped to 0.045)", "clamp the roughness to [0.045, 1] first"}};
    return {g1, g};
}

// ---- 07 F -------------------------------------------------------------------------------

std::vector<ProbeSpec> fresnelProbes() {
    ProbeSpec p{ProbeFunction::FSchlick, "F_Schlick", "F_Schlick(F0, VoH)", 3};
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
    ProbeSpec alpha{ProbeFunction::Alpha, "ggxAlpha", "ggxAlpha(roughness)", 1};
    for (double r : {0.0, 0.01, 0.045, 0.1, 0.3, 0.5, 0.77, 1.0}) {
        ProbeCase c;
        c.in[0] = float(r);
        c.group = r < 0.045 ? "roughness below 0.045 (clamped)" : "roughness";
        alpha.cases.push_back(c);
    }
    alpha.expected = [](const ProbeCase& c) { return value(R::ggxAlpha(f(c, 0))); };
    // r * r: one rounding. 0.045 written 0.05 is 23% off at roughness 0.
    alpha.tolerance = standardTolerance;
    alpha.describe = [](const ProbeCase& c) { return "roughness=" + fmt(f(c, 0)); };
    alpha.mistakes = {
        {"highlights far too wide: alpha = roughness instead of roughness^2",
         "alpha = r * r with r = clamp(roughness, 0.045, 1) (perceptual roughness, Burley 2012)",
         [](const ProbeCase& c) { return value(std::clamp(double(f(c, 0)), 0.045, 1.0)); }},
        {"mirror-like surfaces blow up: roughness is not clamped", "clamp roughness to [0.045, 1] before squaring",
         [](const ProbeCase& c) { return value(double(f(c, 0)) * f(c, 0)); }},
    };

    ProbeSpec f0{ProbeFunction::F0, "baseReflectance", "baseReflectance(material)", 3};
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

    auto brdfSpec = [](ProbeFunction fn, const std::string& name, std::uint64_t seed) {
        ProbeSpec s{fn, name, name + "(n, v, l, material)", 3};
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
    ProbeSpec spec = brdfSpec(ProbeFunction::Specular, "specularBRDF", 811);
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

    ProbeSpec diff = brdfSpec(ProbeFunction::Diffuse, "diffuseBRDF", 812);
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

    ProbeSpec full = brdfSpec(ProbeFunction::Brdf, "cookTorranceBRDF", 813);
    full.expected = [](const ProbeCase& c) { return value(R::cookTorranceBRDF(get(c, 8), get(c, 12), get(c, 16), materialAt(c))); };
    return {alpha, f0, spec, diff, full};
}

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
dvec3 traceVariant(const Scene& scene, dvec3 origin, dvec3 dir, bool attenuate, bool swapReflect) {
    dvec3 radiance(0), throughput(1);
    int leaving = -1;
    for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce) {
        R::Hit hit;
        dir = glm::normalize(dir);  // closestHit() renormalises
        if (closestHitLeaving(scene, origin, dir, leaving, hit) < 0) {
            radiance += throughput * scene.render.background;
            break;
        }
        radiance += throughput * R::shadeHit(scene, hit, -dir);
        const Material& m = scene.spheres[hit.sphere].material;
        double NoV = std::clamp(glm::dot(hit.n, -dir), 1e-4, 1.0);
        if (attenuate) throughput *= R::F_SchlickRoughness(R::baseReflectance(m), NoV, m.roughness);
        origin = hit.p;
        dir = swapReflect ? hit.n - 2 * glm::dot(dir, hit.n) * dir : glm::reflect(dir, hit.n);
        leaving = hit.sphere;
    }
    return radiance;
}

std::vector<ProbeSpec> reflectionProbes() {
    ProbeSpec fr{ProbeFunction::FRoughness, "F_SchlickRoughness", "F_SchlickRoughness(F0, NoV, roughness)", 3};
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

    ProbeSpec tr{ProbeFunction::Trace, "traceRay", "traceRay(origin, dir) in the probe scene", 3};
    tr.needsScene = true;
    Scene scene = makeProbeScene();
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
    tr.groupHints = {{"metal sphere (bounces)", "check the bounce: origin offset, reflect(dir, n), throughput"},
                     {"between two facing mirrors", "stop after the primary hit and maxBounces() bounces"}};
    return {fr, tr};
}

// ---- 10 display -------------------------------------------------------------------------

std::vector<ProbeSpec> displayProbes() {
    Random rng(1010);
    auto radianceValue = [&]() {
        double scale = std::pow(10.0, rng.range(-3, 1.5));
        return float(scale) * rng.colour();
    };
    ProbeSpec tm{ProbeFunction::ToneMap, "toneMap", "toneMap(c, op)", 3};
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

    ProbeSpec gm{ProbeFunction::Gamma, "encodeGamma", "encodeGamma(c, gamma)", 3};
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

    ProbeSpec dp{ProbeFunction::Display, "displayEncode", "displayEncode(radiance, exposure, op, gamma)", 3};
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

Scene probeScene() { return makeProbeScene(); }

std::vector<ProbeSpec> probesForExercise(int number) {
    switch (number) {
        case 1: return cameraProbes();
        case 2: return intersectProbes();
        case 3: return lambertProbes();
        case 4: return shadowProbes();
        case 5: return ggxProbes();
        case 6: return geometryProbes();
        case 7: return fresnelProbes();
        case 8: return cookTorranceProbes();
        case 9: return reflectionProbes();
        case 10: return displayProbes();
        default: return {};
    }
}

}  // namespace rl
