// Where a frame's time goes, part by part, for `--stats`: the render is one
// part; the others are what the render scale does not shrink (issue 37: the
// window's statistics put 1.6 ms in the render and 86-164 ms elsewhere).
// Milliseconds, wall clock, over the frames rendered while moving (a drag,
// a slider) and over all frames, each part's median printed at exit.
//
// On a software renderer (llvmpipe) GL calls only queue work: it runs on
// llvmpipe's threads at the next flush. So that each part is charged with
// its own pixels, the window finishes the GL queue at each part's end, with
// `--stats` only and on every kProfileEvery-th frame only: each finish
// wakes llvmpipe's threads, which on a loaded machine costs frame rate.
// The parts are the medians of those frames; the frame rate (swap to swap)
// is every frame's.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace rl {

class FrameParts {
public:
    enum Part {
        Events,     // glfwPollEvents and the script's step: the window system's queue
        Programs,   // hot reloads, the view's program (compiles, when one is due)
        Render,     // the ray tracer's draw (at the adaptive scale)
        Present,    // the picture to the window: the upscale blit (or the 1:1 copy)
        Overlays,   // the spheres' rectangles, the caption, the asked pixel's rays (own ImGui context)
        UiBuild,    // the panel, help and overlays laid out by ImGui (CPU)
        UiDraw,     // ImGui's vertices drawn into the window
        Swap,       // glfwSwapBuffers: under Xvfb/llvmpipe the copy of every window pixel to the X server
        kCount
    };
    static const char* name(Part p);

    using Clock = std::chrono::steady_clock;
    static constexpr int kProfileEvery = 4;

    // This frame's parts are timed (the GL queue finished at each part's end).
    bool profiled() const { return frame_ % kProfileEvery == 0; }

    // Starts a frame's first part.
    void begin() { last_ = Clock::now(), current_.fill(0.0); }
    // Ends part `p` (its time since the previous mark).
    void mark(Part p) {
        const auto now = Clock::now();
        current_[p] += std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
    }
    // The frame is done: its parts go to the run's lists where it was
    // profiled (`moving`: a drag's frame), its swap to the frame rate's.
    void end(bool moving);
    // One line a part, "render 12.3 ms (moving) / 140.1 ms (all)", for --stats.
    std::string summary() const;
    // The median of part `p` over the profiled moving frames (0 when none).
    double movingMedian(Part p) const;
    // The median time between the swaps of consecutive moving frames: the
    // frame rate the audience sees, events and idle waits included.
    double movingIntervalMs() const;
    std::size_t movingFrames() const { return intervals_.size(); }

private:
    long frame_ = 0;  // frames ended, moving or not
    Clock::time_point last_{};
    std::array<double, kCount> current_{};
    std::array<std::vector<double>, kCount> moving_, all_;
    std::vector<double> intervals_;  // between the swaps of consecutive moving frames
    Clock::time_point lastSwap_{};
    bool lastWasMoving_ = false;
};

}  // namespace rl
