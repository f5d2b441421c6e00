// The pixel debugger ("Ask a pixel", raylab view; raylab render --ask X,Y):
// the ray tracer of the implementation ON SCREEN (the same assembled source:
// its exercise files and the framework, pixel_debug.frag) traces one
// pixel's centre ray again and records the value of every exercise function
// along it: the camera ray (01), each hit (02), each light's irradiance and
// Lambert (03), visibility (04), D (05), G (06), F (07), the Cook-Torrance
// terms (08), each bounce's weight and the radiance (09), the display colour
// (10), and with an environment each hit's environment terms: irradiance,
// prefiltered level and radiance, split-sum scale and bias, visibility and
// the light they make (11; the reference's are the approximation's, in
// double on the same tables: reference/pixel_breakdown.h). One draw into a 1xN RGBA32F target, fragment k writing value k; no
// SSBO, so the same works in WebGL2. Each value is put beside the CPU
// reference's (reference/pixel_breakdown.h, double) and the first one that
// differs beyond float32's tolerance is named with its exercise.
#pragma once

#include "core/scene.h"
#include "render/scene_uniforms.h"
#include "shader/program.h"
#include "shader/shader_library.h"

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace rl {

// What a recorded value is: pixel_debug.glsl's DBG_ constants.
enum class PixelValueKind {
    SampleOffset = 1, CameraRay = 2,
    Ray = 10, Hit = 11, Point = 12, Normal = 13, Miss = 14,
    LightDir = 18, Half = 19, Angles = 20, Irradiance = 21, Lambert = 22, Visibility = 23, D = 24, G = 25, F = 26, Alpha = 27, F0 = 28,
    Diffuse = 29, Specular = 30, Brdf = 31, Shaded = 32,
    EnvIrradiance = 33, EnvLevel = 34, EnvPrefiltered = 35, EnvScaleBias = 36, EnvVisibility = 37, EnvLight = 38,
    Weight = 40, Radiance = 41, Display = 50,
};

struct PixelValue {
    PixelValueKind kind = PixelValueKind::SampleOffset;
    int bounce = 0;   // 0 = the primary hit
    int light = -1;   // lights[light], -1 for none
    glm::dvec3 gl{0.0};                   // the program's (float32; positions and t in the scene's units)
    std::optional<glm::dvec3> reference;  // the CPU reference's; none where its path has no such value
    int components = 3;
    int exercise = 0;       // the course exercise whose function gives it; 0: the framework
    std::string function;   // "D_GGX(n, h, alpha)"
    bool differs = false;   // beyond the tolerance (pixel_debugger.cpp, tolerance())
    double extraTolerance = 0;  // absolute, added to the kind's: a lookup's spread (pixel_breakdown.h, prefilteredSpread)
    double toleranceUsed = 0;  // max over components of |gl - reference| / tolerance (differs: > 1)
    std::string name() const;  // "bounce 1, lights[0]: D"
};

struct PixelDebug {
    int i = 0, j = 0;  // column, row from the BOTTOM of a width x height picture
    int width = 0, height = 0;
    std::string implementation;  // the label of the code on screen
    std::vector<PixelValue> values;  // in the order the program computes them
    int firstDifference = -1;        // index into values; -1: every value within tolerance
    // The display colour (the pixel's final value) is within tolerance of
    // the model's: any difference before it does not reach this pixel (a
    // wrong D in shadow). The answer then leads with the agreement.
    bool pixelAgrees = false;
    bool loopRanAway = false;        // a loop of an exercise file went over its bound
    std::string hint;                // the checker's line for the first difference's exercise (a caller's, checks/)
    const PixelValue* first() const { return firstDifference < 0 ? nullptr : &values[std::size_t(firstDifference)]; }
};

// The debugger's program for `impl` (the model's defines of `scene`, as the
// live view's generic program). Throws ShaderError / rl::Error as buildRayTracer.
ShaderProgram buildPixelDebugProgram(const Implementation& impl, const Scene& scene);

// Needs a current GL context. Runs the program for pixel (i, j) (row from
// the bottom) of a width x height picture of `scene` seen by `camera` and
// puts every value beside the CPU reference's. Throws rl::Error for a pixel
// outside the picture.
PixelDebug debugPixel(const ShaderProgram& program, const Scene& scene, const Camera& camera, int width, int height,
                      int i, int j, const std::string& implementation);

// The raw read-back: (value, key) per recorded value, key 0 past the last.
std::vector<std::array<float, 4>> recordPixelValues(const ShaderProgram& program, const Scene& scene,
                                                    const FrameSettings& frame, int i, int j);

// The functions the debugger records a value of (as their units declare
// them in course/*/unit.json): an exercise with none of them cannot be asked.
std::vector<std::string> askedFunctions();

// The table: one value a line, the program's beside the reference's, the
// first difference marked ">>" and named with its exercise and handout.
std::string formatPixelDebug(const PixelDebug& debug);
// One line: "first difference: ...", or "this pixel agrees with the model"
// and either "every value within float32 tolerance" or the first
// intermediate difference, "not affecting this pixel".
std::string pixelDebugVerdict(const PixelDebug& debug);

// The answer in brief, for a label beside the pixel (view/asked_pixel_label.h):
// the first differing quantity, its function and exercise, the program's and
// the model's values; or that the pixel agrees. At most three short lines.
std::vector<std::string> pixelDebugLabel(const PixelDebug& debug);

}  // namespace rl
