// Helpers of the accuracy suite (issue #6): rendering through the library
// with any implementation and any model variant, a double-precision oracle
// for the ray offset, the model variants, and a probe of the GLSL BRDF.
#pragma once

#include "core/image.h"
#include "core/scene.h"
#include "shader/shader_library.h"

#include <glm/vec3.hpp>

#include <array>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace rl::acc {

// The solutions, with single exercise files replaced: {"02-intersect.glsl",
// "course/02-intersect/mutants/textbook-quadratic.glsl"}.
Implementation solutionsWith(const std::map<std::string, std::filesystem::path>& overrides = {});

// A student's complete submission written differently from the course's:
// every exercise's first alternative (course/NN/alternatives/), the
// course's own file with a comment added where a unit has none.
Implementation alternativesSubmission();

// Renders with OpenGL: one headless context per process, programs cached by
// implementation and defines: Purpose::Generic, the generic program with the
// scene's model defines, or with `specialise` what `raylab render` compiles
// (Purpose::Picture: structure, picture, positions; render/define_table.h).
Rendering renderGlsl(const Scene& scene, const Implementation& impl = solutionsWith(), bool specialise = false);

// What the live view (`raylab view`) draws of the scene's camera: its
// picture program (liveViewDefines(), every value a uniform, the scene block
// uploaded for the camera as each frame does).
Rendering renderGlslLive(const Scene& scene, const Implementation& impl = solutionsWith());

// The probe program of `raylab check` for one exercise (probe.frag with
// RL_PROBE_EXERCISE), for runProbe() (checks/probe_runner.h).
const ShaderProgram& probeProgram(int exercise, const Implementation& impl = solutionsWith());

// The CPU reference's picture (double precision, the same model and the same
// display step) with secondary rays offset by relativeOffset * hit magnitude
// instead of kRayOffsetRelative = 2^-19. With a tiny offset (2^-40) it is
// the oracle for the offset constant itself: what the scene looks like
// without the offset's own error (contact shadows, leaks).
Rendering renderDoubleWithOffset(const Scene& scene, double relativeOffset);

// Every model variant: each switch of ShadingModel away from the reference,
// plus one combination of all PBR switches; the reference model is not in it.
struct NamedModel {
    std::string name;  // "beckmann", "smith-ggx", ..., "beckmann+correlated+conductor+burley"
    ShadingModel model;
};
std::vector<NamedModel> everyModelVariant();
// The reference model ("reference") first, then everyModelVariant().
std::vector<NamedModel> referenceAndVariants();
inline void PrintTo(const NamedModel& m, std::ostream* out) { *out << m.name; }  // gtest parameter names
// A gtest parameter name for a model: its name with every non-alphanumeric as '_'.
std::string modelTestName(const NamedModel& m);

// A scene from scenes/hard/ (throws rl::Error when missing or invalid).
Scene hardScene(const std::string& file);

// Fireflies: pixels whose radiance is non-finite, or brighter (luminance,
// linear) than `factor` times the brightest of their 8 neighbours and than
// `floor`. An isolated bright pixel that no neighbour shares is what a
// numerical blow-up looks like; a highlight that is itself one pixel wide
// looks the same, so newFireflies() counts only those of `got` that the
// double-precision `expected` does not have.
std::vector<bool> fireflies(const RadianceImage& image, double factor = 4.0, double floor = 0.05);
long newFireflies(const RadianceImage& got, const RadianceImage& expected);

// "off 0.12% mean 0.03 p99 1 max 2 pfmRel 1e-6 nonFinite 0", for messages.
std::string describeDiff(const ImageDiff& d);

// ---- GLSL probes of the BRDF (tests/accuracy/brdf_probe.glsl) -----------------------------

// One evaluation: the function, unit vectors n, v, l (or h in place of l for
// the D terms), the material and the edge tint.
enum class BrdfProbe : int {
    Brdf = 0,      // surfaceBRDF(): what directLight() multiplies E with (rgb)
    Specular = 1,  // the specular lobe of the model (rgb)
    Diffuse = 2,   // the diffuse lobe of the model (rgb)
    D = 3,         // the model's D at (n, h = third vector), alpha from roughness (x)
    F = 4,         // the model's F at VoH = dot(v, third vector) ... see brdf_probe.glsl (rgb)
};
struct BrdfCase {
    glm::vec3 n{0, 0, 1}, v{0, 0, 1}, l{0, 0, 1};
    glm::vec3 albedo{1, 1, 1};
    float roughness = 0.5f, metallic = 0.0f;
    glm::vec3 edgeTint{1, 1, 1};
};
// Evaluates `probe` for every case with the GLSL of the solutions compiled
// with modelDefines(model); needs no scene. Returns one rgb per case (what
// the GPU computed, read back as float).
// `impl` may replace exercise files (a naive version, to see a check fail).
std::vector<glm::vec3> runBrdfProbe(BrdfProbe probe, const std::vector<BrdfCase>& cases, const ShadingModel& model,
                                    const Implementation& impl = solutionsWith());

// The double-precision CPU reference for the same case: the float inputs
// widened, the directions renormalised in double.
glm::dvec3 expectedBrdf(BrdfProbe probe, const BrdfCase& c, const ShadingModel& model);

}  // namespace rl::acc
