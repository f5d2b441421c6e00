// What the bench suite's picture-program tests share (test_specialisation,
// test_course_program, test_live_course_program): one headless context, small
// scenes, and the core's error budget between two renderings.
#pragma once

#include "core/scene.h"
#include "core/image.h"

#include <filesystem>
#include <string>

namespace rl::test {

// One headless GL context for the whole test binary (created on first use).
void ensureHeadlessContext();

// `file` at 64x48: llvmpipe, small renders keep the suite fast.
Scene tinyScene(const std::filesystem::path& file);

// The core's budget: at most 0.5% of pixels off by more than 1/255 in any
// channel, mean difference under 0.2/255, no NaN or Inf.
void expectWithinBudget(const Rendering& got, const Rendering& expected, const std::string& what);

}  // namespace rl::test
