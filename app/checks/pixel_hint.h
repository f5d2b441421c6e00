// The checker's word on the exercise where an asked pixel's values first
// differ (render/pixel_debugger.h): that exercise's probe cases run on the
// implementation on screen, and the hint `raylab check` would print.
#pragma once

#include "render/pixel_debugger.h"
#include "shader/shader_library.h"

#include <string>

namespace rl {

// Needs a current GL context. One line: "05-ggx's probes on this code: D_GGX
// fails 38 of 40 cases: <hint>", or that they pass (then the difference comes
// in through the function's inputs). "" when `exercise` is 0 (the framework).
std::string probeHintFor(const Implementation& impl, int exercise);

// debug.hint from probeHintFor() for its first difference; errors while
// compiling the probe become the line.
void addProbeHint(PixelDebug& debug, const Implementation& impl);

}  // namespace rl
