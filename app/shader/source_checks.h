// What the host checks in the exercise files of an assembled shader, so that
// every shader error names the exercise file and line (never a framework
// file), or says plainly that two files disagree:
//   - before compiling (checkExerciseSources): the contract of
//     the units' signatures, exercise_declarations.glsl (every function of the exercise present,
//     with its parameters and return type), a main() in an exercise file,
//     and the same function, variable or macro defined in two exercise files
//     (they are compiled together: `pow5` in 07 and in 09);
//   - after the driver failed (explainDriverDiagnostics): an error at the line
//     that closes an exercise file's scope becomes "this '{' is not closed"
//     or "a ';' is missing", and an error in a framework file about a name an
//     exercise file declares moves to that exercise file's line.
// The scans are linear (shader/glsl_scan.h); nothing here recurses.
#pragma once

#include "shader/program.h"
#include "shader/source_assembler.h"

#include <vector>

namespace rl {

// Errors found before compiling; empty when the driver should decide.
std::vector<ShaderDiagnostic> checkExerciseSources(const AssembledSource& source);

// Rewrites driver diagnostics whose location is not where the mistake is.
void explainDriverDiagnostics(std::vector<ShaderDiagnostic>& diagnostics, const AssembledSource& source);

}  // namespace rl
