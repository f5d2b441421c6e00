// What every unit's probes (course/*/probes.cpp) build their cases from: a
// generator with the same sequence on every platform, the input layout of
// shaders/probe.glsl, the standard float32 tolerance and the probe scene.
// A unit's probes.cpp includes this file, writes its ProbeSpecs and ends with
// RL_UNIT_PROBES { return ...; } (course/README.md).
#pragma once

#include "checks/probe_cases.h"
#include "reference/cpu_reference.h"

#include <glm/geometric.hpp>
#include <glm/gtx/norm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace rl::probes {

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

inline void put(ProbeCase& c, int at, vec3 v) {
    c.in[at] = v.x;
    c.in[at + 1] = v.y;
    c.in[at + 2] = v.z;
}
inline dvec3 get(const ProbeCase& c, int at) { return dvec3(c.in[at], c.in[at + 1], c.in[at + 2]); }
inline double f(const ProbeCase& c, int at) { return c.in[at]; }
inline ProbeValue value(dvec3 v) { return {v.x, v.y, v.z}; }
inline ProbeValue value(double x) { return {x, 0, 0}; }

inline std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return b;
}
inline std::string fmt(dvec3 v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")"; }

inline Material materialAt(const ProbeCase& c) {
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
inline constexpr double kRel = 1e-4;
inline constexpr double kAbs = 1e-6;  // values near zero: a few ulps of the typical magnitude 1e-2..1
inline std::pair<double, double> standardTolerance(const ProbeCase&) { return {kAbs, kRel}; }

// float32's unit roundoff and gamma_k, as in shaders/error_bounds.glsl.
inline constexpr double kUnitRoundoff = 0x1.0p-24;
inline double roundingGamma(double k) { return k * kUnitRoundoff / (1 - k * kUnitRoundoff); }

// Hit.error of a hit on a sphere of radius r with normal n at p, as
// closestHit() computes it (error_bounds.glsl, centre form):
// gamma_12 (|p| + r |n|).
inline vec3 hitError(vec3 p, vec3 n, double r) {
    dvec3 e = roundingGamma(12) * (glm::abs(dvec3(p)) + r * glm::abs(dvec3(n)));
    return vec3(e);
}


}  // namespace rl::probes

// The head of the unit's probe function: the build names it after the unit
// (cmake/course.cmake defines RL_UNIT_SYMBOL for each course/*/probes.cpp).
#define RL_UNIT_PROBES_CAT2(a, b) a##b
#define RL_UNIT_PROBES_CAT(a, b) RL_UNIT_PROBES_CAT2(a, b)
#define RL_UNIT_PROBES std::vector<ProbeSpec> RL_UNIT_PROBES_CAT(unitProbes_, RL_UNIT_SYMBOL)()  // inside namespace rl
namespace rl {
#ifdef RL_UNIT_SYMBOL
std::vector<ProbeSpec> RL_UNIT_PROBES_CAT(unitProbes_, RL_UNIT_SYMBOL)();
#endif
}  // namespace rl
