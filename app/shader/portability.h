// Portable GLSL: the exercise files compiled the strict way, as GLSL ES 3.00
// (WebGL2's language), through the same driver. Mesa's desktop GLSL 3.30
// converts an int to a float wherever one is needed; GLSL ES has no implicit
// conversion at all, and neither do macOS's, some Windows drivers' and every
// browser's compilers. So `pow(x, 5)` passes here and fails on the student's
// laptop. Mesa compiles `#version 300 es` in a desktop context with ES's
// rules, so the check needs nothing but the context it already has.
//
// Each error in an exercise file becomes one line
//     exercises/07-fresnel.glsl:5: portability error: pow(float, int) does not exist in GLSL ES: write `pow(m, 5.0)`
//         return F0 + (1.0 - F0) * pow(m, 5);
// with the fix spelled out where the line shows it (an integer literal
// written as a float, an int expression wrapped in float(...)).
#pragma once

#include "shader/source_assembler.h"

#include <string>

namespace rl {

// What a student reads after a portability error: why Mesa accepted it.
extern const char* const kPortabilityHint;

// Compiles `esSource` (assembled with GlslDialect::Es300) as a fragment
// shader in the current context (compile only: the front end decides) and
// returns the portability errors in exercise files, one per line as above
// (at most a few, then a count), or "" when there are none. Errors the
// driver places in framework files only (a driver without GLSL ES 3.00, say)
// are not the student's and give "".
std::string portabilityErrors(const AssembledSource& esSource);

// The part after "portability error: " for one driver message about the
// source line `line`: what GLSL ES lacks and the line (or call) as it should
// read. Pure: unit-tested on Mesa's messages.
std::string explainPortability(const std::string& driverMessage, const std::string& line);

}  // namespace rl
