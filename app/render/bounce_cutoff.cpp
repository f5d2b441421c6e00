#include "render/bounce_cutoff.h"

#include "reference/brdf_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double maxComponent(const glm::dvec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// Peak over all l and v of f(l, v) NoL for the reference model (spec "Direct
// light"), with r = ref::clampRoughness(roughness), alpha = r^2, k = (r + 1)^2 / 8:
//   diffuse:  kd albedo / pi NoL <= (1 - metallic) albedo / pi   (kd = (1 - F)(1 - metallic), F >= 0)
//   specular: D G F / (4 NoL NoV) NoL = D F G1(NoL) G1(NoV) / (4 NoV)
//             <= 1 / (pi alpha^2) * 1 * 1 * 1 / (4 k)
// since D peaks at n.h = 1 with 1 / (pi alpha^2), F <= 1, G1 <= 1 and
// G1(NoV) / NoV = 1 / (NoV (1 - k) + k) <= 1 / k (k <= 1/2).
double brdfCosinePeak(const Material& m) {
    double r = ref::clampRoughness(m.roughness);
    double alpha = r * r;
    double k = (r + 1.0) * (r + 1.0) / 8.0;
    double diffuse = std::max(0.0, 1.0 - m.metallic) * maxComponent(m.albedo) / kPi;
    double specular = 1.0 / (kPi * alpha * alpha * 4.0 * k);
    return diffuse + specular;
}

}  // namespace

double hitRadianceBound(const Scene& scene) {
    if (!scene.model.isReference()) return kInfinity;
    double bound = 0.0;
    for (const Sphere& s : scene.spheres) {
        double h = scene.render.ambient * maxComponent(s.material.albedo) * s.material.ao;
        double peak = brdfCosinePeak(s.material);
        for (const Light& l : scene.lights) {
            double power = maxComponent(l.color) * l.intensity;
            if (power <= 0.0) continue;
            // The closest point of the sphere's surface to the light, whether
            // the light is outside the sphere or inside it. Below a millionth
            // of the numbers involved, float32 cannot tell the distance from
            // zero: no bound.
            double distance = std::abs(glm::length(l.position - s.center) - s.radius);
            double scale = std::max({glm::length(l.position), glm::length(s.center), s.radius});
            if (distance <= 1e-6 * scale) return kInfinity;
            h += power / (distance * distance) * peak;
        }
        bound = std::max(bound, h);
    }
    return bound;
}

double bounceFresnelBound(const Scene& scene) {
    // Fr = F0 + (max(1 - r, F0) - F0) (1 - NoV)^5 <= max(1 - r, F0) per channel.
    double bound = 0.0;
    for (const Sphere& s : scene.spheres) {
        const Material& m = s.material;
        double r = ref::clampRoughness(m.roughness);
        glm::dvec3 F0 = glm::mix(glm::dvec3(0.04), m.albedo, m.metallic);
        bound = std::max(bound, std::max(1.0 - r, maxComponent(F0)));
    }
    return bound;
}

double rayRadianceBound(const Scene& scene, int hits) {
    double H = hitRadianceBound(scene);
    double Fmax = bounceFresnelBound(scene);
    double background = maxComponent(scene.render.background);
    double R = 0.0;
    for (int k = 1; k <= hits; ++k) R = std::max(background, H + Fmax * R);
    // float32 in the shader against double here: 1% headroom covers its rounding.
    return R * 1.01;
}

glm::vec4 bounceCutoffUniform(const Scene& scene) {
    const RenderSettings& r = scene.render;
    double R = rayRadianceBound(scene, std::max(0, r.maxBounces));
    bool concave = r.srgb || r.gamma >= 1.0;  // x^(1/gamma) is concave for gamma >= 1
    double inverse = (std::isfinite(R) && R > 0.0 && concave) ? 1.0 / (r.exposure * R) : 0.0;
    if (R == 0.0 && concave) inverse = std::numeric_limits<float>::max();  // nothing can come back: stop at once
    return glm::vec4(float(inverse), float(r.exposure / std::max(1, r.spp)), r.srgb ? 0.0f : float(1.0 / r.gamma),
                     float(int(r.tonemap)));
}

double displaySlope(const RenderSettings& render, double c) {
    double T = 0, dT = 0;
    switch (render.tonemap) {
    case ToneMap::Reinhard:
        T = c / (1.0 + c);
        dT = 1.0 / ((1.0 + c) * (1.0 + c));
        break;
    case ToneMap::Exponential:
        T = 1.0 - std::exp(-c);
        dT = std::exp(-c);
        break;
    case ToneMap::None:
        T = std::min(c, 1.0);
        dT = c < 1.0 ? 1.0 : 0.0;
        break;
    }
    T = std::max(T, 1e-30);
    double dG = render.srgb ? (T <= 0.0031308 ? 12.92 : 1.055 / 2.4 * std::pow(T, 1.0 / 2.4 - 1.0))
                            : (1.0 / render.gamma) * std::pow(T, 1.0 / render.gamma - 1.0);
    return dG * dT;
}

}  // namespace rl
