// `raylab bench --sweeps view`: the live view's programs against the generic
// program it drew with before (modelDefines() only), on one scene at the
// view's size (1280x720 unless --size), in one run: compile + link time, the
// first draw (llvmpipe compiles the shader to machine code there), and the
// median time per frame of the picture and of a teaching view. Each picture
// is compared with the generic program's picture of the same view: the live
// programs must draw the same picture, only faster.
// docs/performance.md, "The live view", shows a run.
#pragma once

#include "bench/bench.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace rl::bench {

struct ViewBenchRow {
    // "generic" (the view before issue #12), "before" (the live program before
    // issue #25: the structure's defines, final view only), "live" (what the
    // view draws with now), "textbook" or "expert" (the yardsticks, final view only)
    std::string program;
    std::string view;     // "final", "d", ... (viewName())
    int width = 0, height = 0;
    double compileMs = 0;    // assemble + compile + link, wall clock
    double firstDrawMs = 0;  // the first draw + glFinish (llvmpipe's JIT runs there)
    double msMedian = 0, msMin = 0, msMax = 0;
    int frames = 0;
    std::string clock;  // "gpu", "wall" or "cpu", as bench.h's Clock
    ImageDiff diff;     // against the generic program's picture of the same view
};

// The default size of the view sweep: a lecture-hall window.
constexpr int kViewBenchWidth = 1280, kViewBenchHeight = 720;

// Runs the sweep on options.scenes[0] (scenes/lecture.json when empty) at
// options.width x options.height; progress lines go to `log`.
std::vector<ViewBenchRow> runViewBench(const Options& options, std::ostream& log);

// The table, then per view "live N.NNx faster than generic" (and "than before").
std::string formatViewBench(const std::vector<ViewBenchRow>& rows);

}  // namespace rl::bench
