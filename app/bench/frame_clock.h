// How the bench times a frame: the clocks the bench and the view sweep share.
#pragma once

#include "render/gl_renderer.h"

#include <chrono>
#include <string>
#include <vector>

namespace rl::bench {

// How a frame is timed: GL_TIME_ELAPSED queries; the wall clock around
// draw + glFinish (software rasterisers, whose queries miss the worker
// threads); or the CPU time of the whole process around draw + glFinish
// (software rasterisers on a busy machine: other processes do not inflate it,
// but it adds up the worker threads, so it is about cores x wall time).
enum class Clock { Auto, Gpu, Wall, Cpu };

// Software rasterisers run the fragment shader on worker threads that a
// GL_TIME_ELAPSED query does not cover: llvmpipe answers a few ms, in no
// relation to the ~100 ms a frame takes. There the clock is the wall clock
// around draw + glFinish, which is the frame's cost on a CPU.
bool isSoftwareRasteriser(const std::string& description);

// CPU time of every thread of this process (llvmpipe's workers included), ms.
double processCpuMs();

// Milliseconds of the steady clock since `start`.
double msSince(std::chrono::steady_clock::time_point start);

// One frame of `program` drawn by `renderer`, timed by `clock` (not Auto), ms.
double timeFrame(GlRenderer& renderer, const PictureProgram& program, const FrameSettings& frame, Clock clock);

// The median of `v` (0 for none).
double median(std::vector<double> v);

}  // namespace rl::bench
