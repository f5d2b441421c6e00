#include "render/define_values.h"

#include "core/float_range.h"
#include "render/scene_constants.h"
#include "render/scene_uniforms.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rl {

namespace {

// Higham's gamma_k, as in shaders/error_bounds.glsl.
double roundingGamma(double k) { return k * kFloatUnitRoundoff / (1.0 - k * kFloatUnitRoundoff); }

// Whether makeHit()'s residual form can pay for some point of the sphere
// (shaders/error_bounds.glsl: it is taken where its bound is below the centre
// form's, gamma_12 (max|c_i| + 2r)), the sphere at `centre` relative to the
// scene's anchor (the origin of makeHit()'s coordinates, scene units). Over
// the points p of the sphere, with d = |c|:
//   residual bound >= gamma_10 (|C| + 2 max(d (d - r), 0) + (d - r)^2) / 2r
// (|p|.|c| >= p.c >= d (d - r), |p| >= |d - r|), and max|c_i| <= d. Both
// bounds are sound; the residual form is compiled in only where it can be
// 4 times smaller: a huge sphere near the anchor (a ground of radius 1000
// under the spheres: 4000 times), not a small sphere beside the anchor (at
// most 2.4 times, a few u r either way).
bool residualFormCandidate(glm::dvec3 centre, double radius) {
    double d = glm::length(centre);
    double cAnchor = (d - radius) * (d + radius);
    double residualAtBest = roundingGamma(10) *
                            (std::abs(cAnchor) + 2.0 * std::max(d * (d - radius), 0.0) + (d - radius) * (d - radius)) /
                            (2.0 * radius);
    return 4.0 * residualAtBest < roundingGamma(12) * (d + 2.0 * radius);
}

}  // namespace

std::optional<std::string> refineSphereMask(const Scene& scene) {
    long mask = 0;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i)
        if (refinesRoots(scene, i)) {
            if (i >= 31) return std::nullopt;
            mask |= 1L << i;
        }
    return std::to_string(mask);
}

std::optional<std::string> residualSphereMask(const Scene& scene) {
    const std::size_t spheres = scene.spheres.size();
    if (spheres == 0 || spheres > 31) return std::nullopt;  // the mask is one int
    const glm::dvec3 anchor = sceneAnchor(scene);          // makeHit() works in the anchor's frame
    long residual = 0;
    for (std::size_t i = 0; i < spheres; ++i)
        if (residualFormCandidate(scene.spheres[i].center - anchor, scene.spheres[i].radius)) residual |= 1L << i;
    return std::to_string(residual);
}

std::string sampleGrid(const Scene& scene) {
    return std::to_string(std::max(1, int(std::lround(std::sqrt(double(scene.render.spp))))));
}

std::string cameraFromAnchor(const Scene& scene) {
    const glm::vec3 camera = shaderPosition(scene.camera.position, sceneAnchor(scene),
                                            shaderUnits(scene, scene.camera.position).unit);
    return "vec3(" + floatLiteral(camera.x) + ", " + floatLiteral(camera.y) + ", " + floatLiteral(camera.z) + ")";
}

std::string cameraBasisColumn(const Scene& scene, int column) {
    const glm::mat4 basis = shaderCameraBasis(frameFromScene(scene));
    return vec3Literal(glm::vec3(basis[column]));
}

std::string forEachIndex(std::size_t count) {
    std::string out;
    for (std::size_t i = 0; i < count; ++i) out += " X(" + std::to_string(i) + ")";
    return out;
}

}  // namespace rl
