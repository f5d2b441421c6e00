// The copies rule the bench and its view sweep share (Options::compiles):
// on llvmpipe about one copy in ten of the very same program runs 1.3 to 2x
// slower for as long as it lives (docs/performance.md, "One copy in ten"),
// so each row times the fastest of several copies, every row alike.
#pragma once

#include "render/gl_renderer.h"

#include <functional>
#include <vector>

namespace rl::bench {

// Keeps in `program` (built and drawn once already) the fastest of `copies`
// copies: each further copy comes from `build` and is drawn once (llvmpipe
// compiles and places it there); every copy gets one untimed frame (the copy
// before it evicted it from the caches) and three timed ones, and the copy
// with the smallest median stays. `frameMs` draws one frame of a program and
// returns its time by the bench's clock. Returns each copy's median, in the
// order built (empty where `copies` <= 1: nothing was drawn).
std::vector<double> keepFastestCopy(PictureProgram& program, int copies, const std::function<PictureProgram()>& build,
                                    const std::function<double(const PictureProgram&)>& frameMs);

}  // namespace rl::bench
