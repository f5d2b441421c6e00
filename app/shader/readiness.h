// Which exercise functions are ready, decided by the host from the files of
// an implementation and the course registry (course/exercise_registry.h), and
// compiled into the shader: the framework's GLSL calls every exercise
// function as the model does, and a function that is not ready is replaced by
// its neutral value before the driver sees it.
//
//   started(f) : its file is not the unchanged shipped stub, and f's body does
//                not name NOT_STARTED outside comments
//   ready(f)   : started(f), and ready(g) for every g it needs (the registry)
//
// The generated `exercises.glsl` includes the exercise files in the course's
// order; around the file of a function that is not ready it renames the
// author's definition away (`#define f rl_unfinished_f`) and then defines f
// with the neutral body. It also states the facts, for the stripes
// (unfinished.glsl) and the model variants: `RL_READY_<function>` for each
// ready function and `RL_UNFINISHED` when any is not ready.
#pragma once

#include "shader/shader_library.h"

#include <string>
#include <vector>

namespace rl {

struct FunctionReadiness {
    std::string name;     // "D_GGX"
    int exercise = 0;     // 5
    bool started = false;
    bool ready = false;
};

struct Readiness {
    std::vector<FunctionReadiness> functions;  // every registered function, in the course's order
    bool allReady() const;
    bool isReady(const std::string& function) const;  // false for an unknown name
};

// `probeExercise` (1..10, or 0): a probe program of that exercise
// (RL_PROBE_EXERCISE) evaluates its functions as written, stubs included, so
// they count as ready and are never replaced. Reads the implementation's
// exercise files; a file that cannot be read counts as started (the
// assembler then reports it with its file and line).
Readiness readinessOf(const Implementation& impl, int probeExercise = 0);

// The text of the generated exercises.glsl for `readiness`: the exercise
// files, unfinished functions replaced; the framework units' solutions; the
// units' further light terms (unitLight, RL_UNIT_LIGHT) once they are ready.
std::string exercisesGlsl(const Readiness& readiness);

// exercise_declarations.glsl: the signature of every unit's function
// (shaders/declarations.glsl includes it).
std::string exerciseDeclarationsGlsl();

// probe_dispatch.glsl: each function's probe call (shaders/probe.glsl), for
// the exercise `probeExercise` only, or every unit's when it is 0.
std::string probeDispatchGlsl(int probeExercise);

// The exercise a probe program evaluates: RL_PROBE_EXERCISE of `defines`, or 0.
int probeExerciseOf(const ShaderDefines& defines);

}  // namespace rl
