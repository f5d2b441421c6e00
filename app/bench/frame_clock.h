// How the bench times a frame: the clocks the bench and the view sweep share.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace rl::bench {

// Software rasterisers run the fragment shader on worker threads that a
// GL_TIME_ELAPSED query does not cover: llvmpipe answers a few ms, in no
// relation to the ~100 ms a frame takes. There the clock is the wall clock
// around draw + glFinish, which is the frame's cost on a CPU.
bool isSoftwareRasteriser(const std::string& description);

// CPU time of every thread of this process (llvmpipe's workers included), ms.
double processCpuMs();

// Milliseconds of the steady clock since `start`.
double msSince(std::chrono::steady_clock::time_point start);

// The median of `v` (0 for none).
double median(std::vector<double> v);

}  // namespace rl::bench
