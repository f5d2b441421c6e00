// Frame times for the panel (recent median) and for `--frames N` runs (the
// median over the whole run, printed at exit). Milliseconds throughout.
#pragma once

#include <algorithm>
#include <cstddef>
#include <deque>
#include <vector>

namespace rl {

class FrameStats {
public:
    // Frames shown in the panel's median: about a second at interactive rates,
    // short enough to follow a change of view or resolution.
    static constexpr std::size_t kRecent = 30;

    void addGpu(double ms) { add(gpu_, gpuAll_, ms); }
    void addWall(double ms) { add(wall_, wallAll_, ms); }
    void clearRecent() {
        gpu_.clear();
        wall_.clear();
    }

    double recentGpuMs() const { return median({gpu_.begin(), gpu_.end()}); }
    double recentWallMs() const { return median({wall_.begin(), wall_.end()}); }
    double allGpuMs() const { return median(gpuAll_); }
    double allWallMs() const { return median(wallAll_); }
    std::size_t frames() const { return wallAll_.size(); }
    std::size_t gpuFrames() const { return gpuAll_.size(); }

    static double median(std::vector<double> v) {
        if (v.empty()) return 0.0;
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    }

private:
    static void add(std::deque<double>& recent, std::vector<double>& all, double ms) {
        recent.push_back(ms);
        if (recent.size() > kRecent) recent.pop_front();
        all.push_back(ms);
    }
    std::deque<double> gpu_, wall_;
    std::vector<double> gpuAll_, wallAll_;
};

}  // namespace rl
