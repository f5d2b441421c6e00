#include "checks/pixel_hint.h"

#include "checks/checker.h"
#include "checks/probe_runner.h"
#include "core/error.h"
#include "course/exercise_registry.h"
#include "gl/gl_api.h"

namespace rl {

std::string probeHintFor(const Implementation& impl, int exercise) {
    if (exercise <= 0) return "";
    const ExerciseInfo& info = findExercise(std::to_string(exercise));
    const std::string head = "checker, " + info.id + "'s probes on this code: ";
    ShaderProgram probe(assembleShader("fullscreen.vert", impl, {}),
                        assembleShader("probe.frag", impl, {{"RL_PROBE_EXERCISE", std::to_string(exercise)}}));
    const Scene scene = probeScene();
    for (const ProbeSpec& spec : probesForExercise(exercise)) {
        const ProbeOutcome o = evaluateProbe(spec, runProbe(probe, spec, spec.needsScene ? &scene : nullptr));
        if (o.summary.passed == o.summary.total) continue;
        return head + spec.name + " passes " + std::to_string(o.summary.passed) + " of " +
               std::to_string(o.summary.total) + " cases" + (o.hint.empty() ? "" : ": " + o.hint) + " (" +
               info.handout() + ")";
    }
    return head + "every case passes: the difference comes in through its inputs (" + info.handout() + ")";
}

void addProbeHint(PixelDebug& debug, const Implementation& impl) {
    const PixelValue* first = debug.first();
    if (!first || first->exercise <= 0) return;
    try {
        debug.hint = probeHintFor(impl, first->exercise);
    } catch (const Error& e) {
        const std::string text = e.what();
        debug.hint = "checker: " + text.substr(0, text.find('\n'));
    }
}

}  // namespace rl
