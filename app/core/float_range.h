// What the float32 shader can carry of a scene (docs/numerics.md, "Camera-
// relative coordinates"). The host hands the shader the scene relative to the
// camera, in double until the last step; when even those numbers leave
// float32's comfortable range, lengths are counted in a power-of-two unit
// (exact in binary). A scene value that float32 cannot carry after that is
// an input error: floatRangeProblem() names the field and the limit, and the
// scene loader (scene_io.cpp) rejects the file with it.
#pragma once

#include "core/scene.h"

#include <string>

namespace rl {

// u = 2^-24, float32's unit roundoff: a correctly rounded float32 operation
// on x is off by at most u |x|. The host's one copy of the shaders' constant
// (shaders/common.glsl, UNIT_ROUNDOFF), for the bounds it computes for them.
inline constexpr double kFloatUnitRoundoff = 5.9604644775390625e-8;

// float32's largest finite value and smallest normal one.
constexpr double kFloat32Max = 3.4028234663852886e38;
constexpr double kFloat32MinNormal = 1.1754943508222875e-38;

struct ShaderUnits {
    glm::dvec3 eye{0.0};  // the origin of the shader's coordinates: the camera position
    // Lengths are divided by `unit` (a power of two: exact) and intensities by
    // unit^2, which leaves every radiance unchanged. 1 unless the scene's
    // extent seen from the eye lies outside [2^-50, 2^50].
    double unit = 1.0;
    // True when the whole scene lies within 1e-6 of the eye, below the
    // model's d2 <= 1e-12 at which a light adds nothing (reference-model.md):
    // then no light adds anything, and the host uploads them dark.
    bool lightsTooClose = false;
};
ShaderUnits shaderUnits(const Scene& scene, const glm::dvec3& eye);

// Whether the shader refines the roots of sphere i (error_bounds.glsl,
// refinesRoot): a sphere at least 64 times the radius of the smallest (a
// ground, a room) or the only one. Only there does float32's |o - c|^2 - r^2
// cancel: near a sphere of radius R, at height h, it keeps u R / 2h of
// itself (1% at R = 1e5, h = 0.35); 64 times the smallest sphere is where
// that starts to move a hit on a small sphere's scale. A property of the
// scene alone, so the live view's camera never recompiles a shader.
bool refinesRoots(const Scene& scene, std::size_t i);

// The origin of the coordinates of every ray that leaves a sphere (shadow
// rays, mirror bounces; docs/numerics.md, "Two frames"): the centre of the
// bounding box of the scene's spheres, the huge ones (refinesRoots() by
// size: a ground, a room) left out unless every sphere is huge. Camera rays
// start at the camera, the origin of their own frame; a hit point and the
// rays leaving it then carry float32's rounding of the scene's size, not of
// the camera's distance (a scene seen from 1000 times its size keeps its
// contact shadows). A property of the scene alone: the live view's moving
// camera never moves it.
glm::dvec3 sceneAnchor(const Scene& scene);

// A position as the shader holds it: relative to `anchor`, in `unit`s, in
// double until it is rounded to float32 last. The scene block and the
// numbers compiled into a picture program (render/scene_constants.h: the
// light's-side shadow test is proven exact on exactly these floats) all take
// it from here.
inline glm::vec3 shaderPosition(const glm::dvec3& position, const glm::dvec3& anchor, double unit) {
    return glm::vec3((position - anchor) / unit);
}

// "" when every value of the scene reaches the shader finite and meaningful;
// otherwise "FIELD: VALUE ..., LIMIT" for the first that does not (field
// names as in the scene file: render.exposure, lights[2].intensity, ...).
std::string floatRangeProblem(const Scene& scene);

}  // namespace rl
