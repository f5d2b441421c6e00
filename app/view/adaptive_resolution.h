// Responsiveness on slow machines: while the camera moves, render fewer
// pixels (the picture is upscaled to the window), and the full resolution
// again as soon as it stops. The scale comes from the measured cost per pixel
// and a frame budget, so a fast GPU never drops resolution at all.
#pragma once

namespace rl {

class AdaptiveResolution {
public:
    // While moving, aim for 30 frames a second: the rate at which a drag
    // still feels attached to the mouse.
    static constexpr double kMovingBudgetMs = 1000.0 / 30.0;
    // Never below a quarter of the width: spheres stay recognisable and the
    // upscaled picture still shows where a highlight goes.
    static constexpr double kMinScale = 0.25;
    // Scales are multiples of 1/8, so small changes in the measured cost do
    // not reallocate the render targets every frame.
    static constexpr double kStep = 0.125;

    bool enabled = true;  // panel: "lower resolution while moving"

    // A measured frame: `ms` to render `pixels` pixels.
    void record(double ms, double pixels);
    // The scale of each side of the picture for the next frame.
    double scale(bool moving, int fullWidth, int fullHeight) const;
    double msPerPixel() const { return msPerPixel_; }

private:
    double msPerPixel_ = 0;  // running average; 0 until measured
};

}  // namespace rl
