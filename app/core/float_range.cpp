#include "core/float_range.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rl {

namespace {

// 2^50: beyond it |x|^2 (1.3e30) nears float32's 3.4e38 once a few terms add
// up, and below 2^-50 |x|^2 (7.9e-31) nears its smallest normal 1.2e-38.
constexpr int kComfortableExponent = 50;

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

}  // namespace

ShaderUnits shaderUnits(const Scene& scene, const glm::dvec3& eye) {
    ShaderUnits units;
    units.eye = eye;
    double extent = 0.0;
    for (const Sphere& s : scene.spheres) extent = std::max(extent, glm::length(s.center - eye) + s.radius);
    for (const Light& l : scene.lights) extent = std::max(extent, glm::length(l.position - eye));
    if (extent == 0.0) return units;
    int exponent = std::ilogb(extent);
    if (std::abs(exponent) > kComfortableExponent) units.unit = std::ldexp(1.0, exponent);
    // Any hit point and any light are then within 2 extent of each other.
    units.lightsTooClose = 2.0 * extent <= 1e-6;
    return units;
}

bool refinesRoots(const Scene& scene, std::size_t i) {
    if (scene.spheres.size() == 1) return true;
    double smallest = scene.spheres.at(i).radius;
    for (const Sphere& s : scene.spheres) smallest = std::min(smallest, s.radius);
    return scene.spheres[i].radius >= 64.0 * smallest;
}

glm::dvec3 sceneAnchor(const Scene& scene) {
    if (scene.spheres.empty()) return scene.camera.position;
    double smallest = scene.spheres[0].radius;
    for (const Sphere& s : scene.spheres) smallest = std::min(smallest, s.radius);
    auto huge = [&](const Sphere& s) { return s.radius >= 64.0 * smallest; };
    bool anySmall = std::any_of(scene.spheres.begin(), scene.spheres.end(), [&](const Sphere& s) { return !huge(s); });
    glm::dvec3 low(INFINITY), high(-INFINITY);
    for (const Sphere& s : scene.spheres) {
        if (anySmall && huge(s)) continue;
        low = glm::min(low, s.center);
        high = glm::max(high, s.center);
    }
    return 0.5 * low + 0.5 * high;  // no overflow for centres near double's limit
}

std::string floatRangeProblem(const Scene& scene) {
    auto tooLarge = [](const std::string& field, double value) {
        return field + " is " + number(value) + ", beyond float32's largest value " + number(kFloat32Max) +
               " (the shader computes in float32)";
    };
    const RenderSettings& r = scene.render;
    if (r.ambient > kFloat32Max) return tooLarge("render.ambient", r.ambient);
    if (r.exposure > kFloat32Max) return tooLarge("render.exposure", r.exposure);
    if (!r.srgb && r.gamma > kFloat32Max) return tooLarge("render.gamma", r.gamma);
    for (int k = 0; k < 3; ++k)
        if (r.background[k] > kFloat32Max) return tooLarge("render.background", r.background[k]);
    // tan(fov_y / 2) scales the camera's right and up vectors (camera.glsl):
    // below 1e-15 the pixel directions' squares underflow float32.
    double t = std::tan(0.5 * scene.camera.fovYDegrees * 3.14159265358979323846 / 180.0);
    if (t < 1e-15)
        return "camera.fov_y is " + number(scene.camera.fovYDegrees) +
               " degrees, below 1.15e-13, where the pixel directions underflow float32";
    ShaderUnits units = shaderUnits(scene, scene.camera.position);
    std::string unitNote = units.unit == 1.0 ? "" : " (in the shader's unit of " + number(units.unit) + ")";
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        double strongest = l.intensity * std::max(l.color.x, std::max(l.color.y, l.color.z));
        if (strongest / (units.unit * units.unit) > kFloat32Max)
            return tooLarge("lights[" + std::to_string(i) + "].intensity", l.intensity) + unitNote;
    }
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        double r2 = std::pow(scene.spheres[i].radius / units.unit, 2);
        if (r2 < kFloat32MinNormal)
            return "spheres[" + std::to_string(i) + "].radius is " + number(scene.spheres[i].radius) +
                   ", too small for float32" + unitNote + ": its square is below float32's smallest normal value " +
                   number(kFloat32MinNormal);
    }
    // Points the camera sees that float32 cannot place (issue #23): relative
    // to the anchor a position rounds by u = 2^-24 of its distance, and the
    // shader stops telling points apart where that exceeds the scene's
    // smallest features. kSeeingLimit = 2^22: float32 then still places a
    // point to a quarter of them.
    constexpr double kSeeingLimit = 4194304.0;
    double smallest = INFINITY;
    std::size_t smallestIndex = 0;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (scene.spheres[i].radius < smallest) smallest = scene.spheres[smallestIndex = i].radius;
    const glm::dvec3 eye = scene.camera.position;
    const double pixelAngle = 2.0 * t / std::max(1, scene.render.height);  // the angle of a pixel near the centre
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        double distance = glm::length(eye - s.center);
        std::string field = "spheres[" + std::to_string(i) + "]";
        // The camera inside: its far wall lies up to 2r away, rounded by u 2r.
        if (distance < s.radius && 2.0 * s.radius > kSeeingLimit * smallest)
            return field + ".radius is " + number(s.radius) + " with the camera inside it: float32 rounds its far wall, " +
                   number(2.0 * s.radius) + " away, by more than a quarter of spheres[" + std::to_string(smallestIndex) +
                   "].radius " + number(smallest) + " (at most 4.19e+06 times it, 2^22)";
        // Seen from outside, more than a pixel wide, from more than 2^22 radii:
        // float32 rounds the points on it by more than a quarter of its radius.
        double gap = distance - s.radius;
        if (gap > kSeeingLimit * s.radius && s.radius > gap * pixelAngle)
            return field + ".center is " + number(gap) + " from the camera, " + number(gap / s.radius) +
                   " times its radius " + number(s.radius) + ", and the field of view shows it more than a pixel wide: " +
                   "float32 cannot place points on it (at most 4.19e+06 times, 2^22)";
    }
    return "";
}

}  // namespace rl
