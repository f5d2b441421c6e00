// The scene's numbers compiled into a program for one scene (shaders/scene.glsl
// reads each through one accessor): the values of the define table's data
// rows (render/define_table.cpp), each a function-like macro that picks an
// index's value by a chain of selects, data only, the same float32 values
// the uniform block would hold (render/scene_uniforms.h, shaderScene()).
//
// Why: on llvmpipe a constant folds into the code that reads it, where a
// uniform is a load per use that nothing folds. The lecture scene's frame,
// the same program otherwise, took 2.5 times as long with its spheres and
// lights read from the uniform block (docs/performance.md).
#pragma once

#include "core/scene.h"
#include "render/scene_uniforms.h"

#include <optional>
#include <string>

namespace rl {

// A GLSL float literal that reads back as exactly x (9 significant digits
// round-trip a float32).
std::string floatLiteral(float x);

// `(index) == 0 ? v0 : (index) == 1 ? v1 : ... : vn`, equal values merged
// into one test (`(index) == 0 || (index) == 3 ? v0 : ...`); the last value
// is the default, so an index out of range reads it.
std::string selectChain(const std::string& index, const std::vector<std::string>& values);

// The scene's numbers from its own camera (the camera of `raylab render`).
ShaderScene sceneNumbers(const Scene& scene);

// The macro values of the data rows, for `scene` seen from its camera.
std::string sphereGeometryMacro(const Scene& scene);  // RL_SPHERE_GEOMETRY(i): vec4 centre, radius
std::string sphereAnchorCMacro(const Scene& scene);   // RL_SPHERE_ANCHOR_C(i): float
std::string sphereMaterialMacro(const Scene& scene);  // RL_SPHERE_MATERIAL(i): Material
std::string sphereEdgeTintMacro(const Scene& scene);  // RL_SPHERE_EDGE_TINT(i): vec3
std::string lightPositionMacro(const Scene& scene);   // RL_LIGHT_POSITION(i): vec3
std::string lightIntensityMacro(const Scene& scene);  // RL_LIGHT_INTENSITY(i): vec3
std::string lightSurfaceMacro(const Scene& scene);    // RL_LIGHT_SURFACE(k): vec2 sphere, side
std::string cameraSphereMacro(const Scene& scene);    // RL_CAMERA_SPHERE(i): vec2 C, host decides
std::string vec3Literal(const glm::vec3& v);

// The light-side shadow test (shaders/shadow_light_side.glsl), chosen per
// sphere j: where it is exact for every light k (light k outside sphere j by
// more than float32 can blur, not on its surface, no farther from it than
// twice the size of the scene's small spheres; sphere j neither one of the
// huge spheres whose roots the shader refines nor meeting, touching or
// repeating another; the test's products within float32's range).
//   RL_SHADOW_STEPS(X, Y): " X(0) Y(1) ..." for the spheres, X where the
//     light's side decides, Y where the segment test does;
//   RL_LIGHT_OCCLUDERS: vec4[](...), light-major, vec4(L - c, |L - c|^2 - r^2)
//     for every light and sphere, from double.
// None where no sphere takes the light's side, or the pairs of lights and
// spheres exceed kLightSidePairs.
inline constexpr std::size_t kLightSidePairs = 256;
std::optional<std::string> shadowStepsMacro(const Scene& scene);
std::string lightOccludersArray(const Scene& scene);

}  // namespace rl
