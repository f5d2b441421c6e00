// Runs one probe (shaders/probe.glsl with an exercise function selected) on
// the GPU: uploads the cases' inputs as an RGBA32F texture, draws one pixel
// per case into an RGBA32F target and reads the results back.
#pragma once

#include "checks/probe_cases.h"
#include "shader/program.h"

#include <array>
#include <vector>

namespace rl {

// Needs a current GL context. `scene` is uploaded when the probe needs one.
std::vector<std::array<float, 4>> runProbe(const ShaderProgram& probeProgram, const ProbeSpec& spec,
                                           const Scene* scene);

}  // namespace rl
