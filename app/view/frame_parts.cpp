#include "view/frame_parts.h"

#include "view/frame_stats.h"

#include <cstdio>

namespace rl {

const char* FrameParts::name(Part p) {
    static const char* const names[] = {"events", "programs", "render", "present", "overlays", "ui build", "ui draw", "swap"};
    return p >= 0 && p < kCount ? names[p] : "?";
}

void FrameParts::end(bool moving) {
    const auto now = Clock::now();
    for (int p = 0; p < kCount && profiled(); ++p) {
        all_[std::size_t(p)].push_back(current_[std::size_t(p)]);
        if (moving) moving_[std::size_t(p)].push_back(current_[std::size_t(p)]);
    }
    if (moving && lastWasMoving_) intervals_.push_back(std::chrono::duration<double, std::milli>(now - lastSwap_).count());
    lastWasMoving_ = moving;
    lastSwap_ = now;
    ++frame_;
}

double FrameParts::movingMedian(Part p) const { return FrameStats::median(moving_[std::size_t(p)]); }

double FrameParts::movingIntervalMs() const { return FrameStats::median(intervals_); }

std::string FrameParts::summary() const {
    std::string out;
    char line[160];
    for (int p = 0; p < kCount; ++p) {
        std::snprintf(line, sizeof line, "%s%s %.1f", out.empty() ? "" : ", ", name(Part(p)),
                      FrameStats::median(moving_[std::size_t(p)]));
        out += line;
    }
    std::snprintf(line, sizeof line, " ms (median of %zu profiled moving frames, one in %d; all %zu profiled:", moving_[0].size(), kProfileEvery, all_[0].size());
    out += line;
    for (int p = 0; p < kCount; ++p) {
        std::snprintf(line, sizeof line, " %s %.1f", name(Part(p)), FrameStats::median(all_[std::size_t(p)]));
        out += line;
    }
    return out + ")";
}

}  // namespace rl
