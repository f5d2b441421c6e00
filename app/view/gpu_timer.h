// GPU time of each rendered frame from GL_TIME_ELAPSED queries, read back
// frames later from a ring so that the CPU never waits for the GPU
// (GlRenderer::drawTimed waits; fine for a benchmark, not for a live window).
#pragma once

#include "gl/gl_api.h"

#include <array>
#include <optional>

namespace rl {

class GpuTimer {
public:
    GpuTimer();
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    struct Result {
        double ms = 0;   // GPU time of the frame
        double tag = 0;  // what begin() was given, e.g. the pixels rendered
    };

    // Around the GL work of one frame. begin() returns false (and end() does
    // nothing) when every query is still in flight: that frame is not timed.
    bool begin(double tag = 0);
    void end();
    // Results that are ready, oldest first; nullopt when none is. Never blocks.
    std::optional<Result> poll();

private:
    // Four in flight: drivers queue at most about three frames, so the oldest
    // query is normally ready by the time its slot comes round again.
    static constexpr int kQueries = 4;
    std::array<GLuint, kQueries> queries_{};
    std::array<double, kQueries> tags_{};
    int head_ = 0;     // next slot to begin
    int pending_ = 0;  // ended, not yet read (the oldest is head_ - pending_)
    bool running_ = false;
};

}  // namespace rl
