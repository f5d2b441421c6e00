// Probe cases: for each exercise, the functions it implements, a grid of
// inputs (random ones and hard ones), the value the double-precision CPU
// reference expects, the float32 tolerance (justified at each use) and the
// typical mistakes the checker recognises by their numbers. Each unit writes
// its own in course/NN-name/probes.cpp (with checks/probe_toolkit.h).
#pragma once

#include "core/scene.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rl {

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
    ProbeSpec(std::string n, std::string sig, int outs)
        : name(std::move(n)), signature(std::move(sig)), outputs(outs) {}
    std::string name;          // "F_Schlick": the function (its probe id: probeFunctionId), or "reintersect"
    // u_probeFunction for a probe program of a test's own (not probe.glsl);
    // unset: chosen by `name`.
    std::optional<int> programFunction;
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

// The probes of the unit `id` ("05-ggx"), from its course/05-ggx/probes.cpp,
// in the order they are checked (the generated course_probes.cpp).
std::vector<ProbeSpec> unitProbes(const std::string& id);
// The same by the exercise's number (5), for the course's exercises.
std::vector<ProbeSpec> probesForExercise(int number);

// u_probeFunction of the framework's own probe (shaders/probe.glsl, PROBE_REINTERSECT).
constexpr int kReintersectProbe = -2;

// The scene uploaded for probes that trace rays (visibility, traceRay).
Scene probeScene();

}  // namespace rl
