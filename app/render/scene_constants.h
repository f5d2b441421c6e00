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

// How much of a scene a program writes out, test by test. Written out, every
// index is a constant and each sphere's numbers fold into its tests; the
// code, and the compile time with it, grows with the tests a bounce makes:
// a nearest-hit test per sphere and a shadow test per light and sphere,
// spheres x (lights + 1). On llvmpipe each costs about 15-20 ms of compile
// time, and saves far more per frame: tests/bench/random-30.json (30 x 7 =
// 210 tests) builds in 3.9 s written out and draws a 640x480 frame in 90 ms,
// where looped over the uniform block it builds in 0.5 s and draws in 458 ms
// (docs/performance.md, "Compile time"). Beyond the budget (a 64-sphere
// scene with 16 lights built for 23 s) the spheres are looped over and read
// from the uniform block, as in the generic program; the lights are written
// out up to kWrittenOutLights (each a copy of the shading, not of the
// sphere tests).
inline constexpr std::size_t kWrittenOutTests = 256;
inline constexpr std::size_t kWrittenOutLights = 16;
bool writesSpheresOut(const Scene& scene);
bool writesLightsOut(const Scene& scene);

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
// None where no sphere takes the light's side, or where the spheres or the
// lights are not written out (writesSpheresOut(), writesLightsOut()).
std::optional<std::string> shadowStepsMacro(const Scene& scene);
std::string lightOccludersArray(const Scene& scene);

}  // namespace rl
