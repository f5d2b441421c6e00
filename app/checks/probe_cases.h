// Probe cases: for each exercise, the functions it implements, a grid of
// inputs (random ones and hard ones), the value the double-precision CPU
// reference expects, the float32 tolerance (justified at each use) and the
// typical mistakes the checker recognises by their numbers.
#pragma once

#include "core/scene.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace rl {

// The same list as the PROBE_ constants of shaders/probe.glsl.
enum class ProbeFunction : int {
    SampleOffset = 0, CameraRay, Intersect, Lambert, Irradiance, OffsetOrigin, Visibility, DGgx, G1, G,
    FSchlick, Alpha, F0, Specular, Diffuse, Brdf, FRoughness, Trace, ToneMap, Gamma, Display,
    Reintersect  // the re-intersection yardstick of the metamorphic suite, not a check
};

constexpr int kProbeInputFloats = 24;  // six RGBA texels per case

// What every exercise stub returns (NOT_STARTED in shaders/common.glsl).
constexpr float kNotStarted = -1.0e30f;

struct ProbeCase {
    std::array<float, kProbeInputFloats> in{};
    std::string group;  // what kind of input: "random", "grazing view", "far sphere (1e4)", ...
};

using ProbeValue = std::array<double, 3>;

// A typical mistake, recognised when the student's results match what the
// mistaken formula gives (on most of the cases where it differs from the
// right one).
struct KnownMistake {
    std::string symptom;  // what the student sees: "highlights too bright by a factor pi"
    std::string hint;     // what to look at: "D = alpha^2 / (pi ...): the 1/pi is missing"
    std::function<ProbeValue(const ProbeCase&)> compute;
};

struct ProbeSpec {
    ProbeSpec(ProbeFunction f, std::string n, std::string sig, int outs)
        : function(f), name(std::move(n)), signature(std::move(sig)), outputs(outs) {}
    ProbeFunction function;
    std::string name;          // "F_Schlick"
    std::string signature;     // "F_Schlick(F0, VoH)": the columns of the failure table
    int outputs = 1;           // 1, 2 or 3 components compared
    std::vector<ProbeCase> cases;
    std::function<ProbeValue(const ProbeCase&)> expected;
    // Tolerance of one component: |got - expected| <= abs + rel |expected|.
    std::function<std::pair<double, double>(const ProbeCase&)> tolerance;
    std::function<std::string(const ProbeCase&)> describe;  // the inputs, for the table
    std::vector<KnownMistake> mistakes;
    std::vector<std::pair<std::string, std::string>> groupHints;  // group -> hint when failures concentrate there
    bool needsScene = false;   // evaluated with probeScene() uploaded
};

// The probes of exercise `number` (1..10), in the order they are checked.
std::vector<ProbeSpec> probesForExercise(int number);

// The scene uploaded for probes that trace rays (visibility, traceRay).
Scene probeScene();

}  // namespace rl
