// What the bench suite's tests share (test_specialisation, test_bench_cli,
// test_environment_sweep): one
// headless context, small scenes, the core's error budget between two
// renderings, and the bench's CSV read back.
#pragma once

#include "core/scene.h"
#include "core/image.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rl::test {

// One headless GL context for the whole test binary (created on first use).
void ensureHeadlessContext();

// `file` at 64x48: llvmpipe, small renders keep the suite fast.
Scene tinyScene(const std::filesystem::path& file);

// The core's budget: at most 0.5% of pixels off by more than 1/255 in any
// channel, mean difference under 0.2/255, no NaN or Inf.
void expectWithinBudget(const Rendering& got, const Rendering& expected, const std::string& what);

// Splits one CSV line into fields (double-quoted fields may hold commas).
std::vector<std::string> csvFields(const std::string& line);

// The CSV as one map per row, header names as keys; a row with another
// number of fields than the header fails the test.
std::vector<std::map<std::string, std::string>> readCsv(const std::string& text);

}  // namespace rl::test
