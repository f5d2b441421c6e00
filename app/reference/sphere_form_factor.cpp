// The form factor of a sphere (Snyder 1996; Lagarde
// and de Rousiers 2014, "Moving Frostbite to PBR", the sphere light's
// illuminance), as docs/model.md writes it.
#include "reference/sphere_form_factor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::ref {

double sphereFormFactor(double h, double cosBeta) {
    const double pi = 3.14159265358979323846;
    const double h2 = h * h;
    const double k2 = 1.0 - h2 * cosBeta * cosBeta;
    if (k2 <= 0.0) return std::max(cosBeta, 0.0) / h2;
    const double x = std::sqrt(h2 - 1.0);
    const double sinBeta = std::sqrt(std::max(1.0 - cosBeta * cosBeta, 0.0));
    const double k = std::sqrt(k2);
    const double clipped = (cosBeta * std::acos(std::clamp(-x * cosBeta / sinBeta, -1.0, 1.0)) - x * k) / h2 + std::atan2(k, x);
    return std::clamp(clipped / pi, 0.0, 1.0);
}

double sphereFormFactor(glm::dvec3 p, glm::dvec3 n, glm::dvec3 centre, double radius) {
    const glm::dvec3 toCentre = centre - p;
    const double d = glm::length(toCentre);
    return sphereFormFactor(d / radius, glm::dot(n, toCentre / d));
}

double summedFormFactors(const std::vector<Sphere>& spheres, int own, glm::dvec3 p, glm::dvec3 n) {
    double sum = 0;
    for (int k = 0; k < int(spheres.size()); ++k) {
        if (k == own) continue;
        const double d = glm::length(spheres[std::size_t(k)].center - p);
        sum += d <= spheres[std::size_t(k)].radius ? 1.0 : sphereFormFactor(p, n, spheres[std::size_t(k)].center, spheres[std::size_t(k)].radius);
    }
    return sum;
}

}  // namespace rl::ref
