#include "render/shadow_cones.h"

#include "core/float_range.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl {

std::vector<ShadowCone> shadowCones(const Scene& scene) {
    // The float32 values of the scene block (SceneUniformBlock::upload), so
    // that only the shader's own arithmetic is left to cover.
    const glm::dvec3 anchor = sceneAnchor(scene);
    const double unit = shaderUnits(scene, scene.camera.position).unit;
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    for (const Sphere& s : scene.spheres) {
        centres.push_back(glm::dvec3(shaderPosition(s.center, anchor, unit)));
        radii.push_back(double(float(s.radius / unit)));
    }
    std::vector<ShadowCone> cones;
    for (const Light& l : scene.lights) {
        const glm::dvec3 light(shaderPosition(l.position, anchor, unit));
        // The farthest any shadow ray's origin can lie from the light: the
        // exact test rounds by a few u of |centre - origin| <= d + farthest.
        double farthest = 0.0;
        for (std::size_t j = 0; j < centres.size(); ++j)
            farthest = std::max(farthest, glm::length(centres[j] - light) + radii[j]);
        for (std::size_t j = 0; j < centres.size(); ++j) {
            const glm::dvec3 toCentre = centres[j] - light;
            const double d = glm::length(toCentre);
            const double margin = 1e-5 * (farthest + d);
            ShadowCone cone;  // a candidate always: the light inside the sphere or at its surface
            if (d > radii[j] + margin) {
                const double sine = (radii[j] + margin) / d;
                cone.axis = glm::vec3(toCentre / d);
                cone.minCos = float(std::sqrt(1.0 - sine * sine) - 1e-6);
                cone.nearest = float((d - radii[j] - margin) * (1.0 - 1e-6));
            }
            cones.push_back(cone);
        }
    }
    return cones;
}

}  // namespace rl
