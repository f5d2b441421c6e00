#include "bench/fastest_copy.h"

#include "bench/frame_clock.h"

namespace rl::bench {

std::vector<double> keepFastestCopy(PictureProgram& program, int copies, const std::function<PictureProgram()>& build,
                                    const std::function<double(const PictureProgram&)>& frameMs) {
    std::vector<double> trials;
    if (copies <= 1) return trials;
    constexpr int kTrialFrames = 3;  // a slow copy is 1.3x and more: three frames tell it apart
    auto trial = [&](const PictureProgram& p) {
        frameMs(p);  // warm
        std::vector<double> t;
        for (int k = 0; k < kTrialFrames; ++k) t.push_back(frameMs(p));
        return median(t);
    };
    double best = trial(program);
    trials.push_back(best);
    for (int copy = 1; copy < copies; ++copy) {
        PictureProgram other = build();
        frameMs(other);  // llvmpipe compiles here
        const double t = trial(other);
        trials.push_back(t);
        if (t < best) {
            best = t;
            program = std::move(other);
        }
    }
    return trials;
}

}  // namespace rl::bench
