// What the bench's expert yardstick (bench/expert.cpp) knows about its
// scene, computed on the host in double, and how it writes numbers and its
// GLSL pieces. The yardstick is the one copy of the model written outside
// the framework's GLSL (docs/decisions.md, "One program"): nothing of raylab's
// own programs reads this file, so the yardstick does not move with what it
// measures.
#pragma once

#include "core/scene.h"

#include <glm/vec3.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace rl::scene_facts {

inline constexpr double kPi = 3.14159265358979323846;

// A float32 literal that reads back as the same float.
inline std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", double(float(v)));
    std::string s = text;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}
inline std::string vec(const glm::dvec3& v) { return "vec3(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

template <class T, class F>
std::string array(const char* type, const std::vector<T>& items, F&& text) {
    std::string s = std::string(type) + "[" + std::to_string(items.size()) + "](";
    for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + text(items[i]);
    return s + ")";
}

inline std::string bit(int j) { return std::to_string(1u << (j % 32)) + "u"; }

// What the host knows about the scene, in double.
struct Facts {
    int n = 0;                       // spheres
    double scale = 1;                // every length below is multiplied by it
    std::vector<glm::dvec3> c;       // centres relative to the camera
    std::vector<double> r, cc;       // radius, |c|^2 - R^2 (camera outside where > 0)
    std::vector<glm::dvec3> light;   // lights relative to the camera
    // Per light, in the scene's own units: the least and the greatest
    // distance from it to a point of some sphere's surface. The model's
    // d2 <= 1e-12 (a light on the surface adds nothing): a light with
    // farthest^2 <= 1e-12 adds nothing anywhere; the test is written only
    // where nearest^2 <= 1e-12.
    std::vector<double> lightNearest, lightFarthest;
    // Nothing starts inside a sphere: the camera is outside every sphere and
    // no two spheres overlap, so every hit is from outside, every bounce ray
    // starts outside every sphere and no point of a surface lies inside
    // another sphere (touching is allowed).
    bool simple = true;
    // huge[i]: a sphere far larger than every other (a ground): the float
    // |p - c|^2 - R^2 of a point near it cancels, so rays that start on
    // another sphere take it from that sphere's centre (constants per pair).
    std::vector<bool> huge;
    // may[l][k]: bit j set when sphere j can block light l for some point of
    // receiver k (j != k); the receiver itself is handled apart.
    std::vector<std::vector<std::vector<bool>>> may;
};

// Whether sphere j can meet a segment from light L to a point of sphere k
// (scene_facts.cpp).
bool mayBlock(const glm::dvec3& L, const glm::dvec3& ck, double rk, const glm::dvec3& cj, double rj);

Facts factsOf(const Scene& scene);

// The per-sphere tables of a generated shader (lines `const T NAME[N] =
// T[N](v0, ...);`, read as NAME[index]) that hold at most `maxDistinct`
// different values, written as functions of selects instead (NAME(index):
// `index == 2 || index == 5 ? v : ...`, the most frequent value last, with
// no test). On llvmpipe a dynamically indexed const array is built anew by
// every 8-pixel group and a uniform array is a gather per component: a few
// selects per component cost less (`raylab bench`, docs/performance.md,
// "Tables as selects"). A rule any hand-written shader can follow, so both
// the expert yardstick uses it. Other lines unchanged.
inline constexpr int kSelectTableMax = 8;
std::string selectTables(const std::string& text, int maxDistinct = kSelectTableMax);

}  // namespace rl::scene_facts
