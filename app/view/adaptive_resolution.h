// Responsiveness on slow machines: while the camera moves, render fewer
// pixels (the picture is upscaled to the window), and the full resolution
// again as soon as it stops. The scale comes from the measured cost per pixel
// and a frame budget, so a fast GPU never drops resolution at all.
//
// A frame is the render (cost per rendered pixel) plus what does not shrink
// with the render scale: the upscale to the window, the panel and captions,
// the swap (on llvmpipe under X, a copy of every window pixel). At 1080p on
// two cores that overhead is most of the budget, so the render gets only what
// the overhead leaves (measured, not guessed: recordFrame()).
#pragma once

namespace rl {

class AdaptiveResolution {
public:
    // While moving, at least 30 frames a second: the rate at which a drag
    // still feels attached to the mouse. The budget aims at 36: a budget of
    // exactly 1/30 s puts the median frame at 30 fps and half the frames
    // below it on a loaded machine (issue 37: 24.8-35.7 fps over four
    // scripted drags at 1920x1080 with two busy processes).
    static constexpr double kMovingBudgetMs = 1000.0 / 36.0;
    // As low as the budget needs, but never fewer than 36 rows: at 1080p
    // that is 1/30 of the height, and a lecture-scene sphere is still ~4 rows
    // tall, enough to follow the drag (llvmpipe at 1080p needs ~1/9).
    static constexpr int kMinRows = 36;
    // Scales are powers of 1/sqrt(2) (each step halves the pixels), so small
    // changes in the measured cost do not reallocate the render targets
    // every frame, and a slow machine reaches its scale in a few steps.
    static constexpr double kStepRatio = 0.70710678118654752;

    bool enabled = true;  // panel: "adaptive resolution"

    // A measured frame: `ms` to render `pixels` pixels.
    void record(double ms, double pixels);
    // A whole frame while moving: `frameMs` from the start of the frame to
    // the swap, of which `renderMs` the render (the rest is the overhead).
    void recordFrame(double frameMs, double renderMs);
    // The scale of each side of the picture for the next frame.
    double scale(bool moving, int fullWidth, int fullHeight) const;
    double msPerPixel() const { return msPerPixel_; }
    double overheadMs() const { return overheadMs_; }

private:
    double msPerPixel_ = 0;  // running average; 0 until measured
    double overheadMs_ = 0;  // running average of a frame's time outside the render
};

}  // namespace rl
