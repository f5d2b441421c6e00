#include "core/light_surface.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {
double maxAbs(const glm::dvec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }
}  // namespace

double surfaceDistance(const glm::dvec3& point, const Sphere& sphere) {
    // |f| rounds by a few roundoffs of |f| <= |point| + |centre|, far below
    // the tolerance of lightSurfaceSide().
    return glm::length(point - sphere.center) - sphere.radius;
}

int lightSurfaceSide(const glm::dvec3& light, const Sphere& sphere) {
    double distance = surfaceDistance(light, sphere);
    double scale = maxAbs(light) + maxAbs(sphere.center) + sphere.radius;
    if (std::abs(distance) <= kLightOnSurfaceTolerance * scale) return 0;
    return distance < 0.0 ? -1 : 1;
}

}  // namespace rl
