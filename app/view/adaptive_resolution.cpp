#include "view/adaptive_resolution.h"

#include <algorithm>
#include <cmath>

namespace rl {

void AdaptiveResolution::record(double ms, double pixels) {
    if (pixels <= 0 || !(ms > 0)) return;
    const double sample = ms / pixels;
    // Weight 0.3: follows a change of scene or view within a few frames while
    // smoothing the jitter of single frames.
    msPerPixel_ = msPerPixel_ == 0 ? sample : 0.7 * msPerPixel_ + 0.3 * sample;
}

void AdaptiveResolution::recordFrame(double frameMs, double renderMs) {
    const double overhead = std::max(frameMs - renderMs, 0.0);
    if (!(overhead < 1e6)) return;  // NaN or absurd: not a frame
    overheadMs_ = overheadMs_ == 0 ? overhead : 0.7 * overheadMs_ + 0.3 * overhead;
}

double AdaptiveResolution::scale(bool moving, int fullWidth, int fullHeight) const {
    if (!enabled || !moving || msPerPixel_ == 0) return 1.0;
    const double fullMs = msPerPixel_ * double(fullWidth) * double(fullHeight);
    // What the render may take: the budget less the overhead, but at least a
    // tenth of it (an overhead over budget cannot be rendered away; the
    // smallest picture is then the best there is).
    const double renderBudget = std::max(kMovingBudgetMs - overheadMs_, 0.1 * kMovingBudgetMs);
    if (fullMs <= renderBudget) return 1.0;
    const double s = std::sqrt(renderBudget / fullMs);  // both sides shrink: cost goes with s^2
    // The largest power of kStepRatio not above s (1e-9: s exactly a power stays that power).
    const double steps = std::ceil(std::log(s) / std::log(kStepRatio) - 1e-9);
    const double quantised = std::pow(kStepRatio, steps);
    const double floor = std::min(1.0, double(kMinRows) / std::max(fullHeight, 1));
    return std::clamp(quantised, floor, 1.0);
}

}  // namespace rl
