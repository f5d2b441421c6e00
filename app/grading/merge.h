// `raylab grade merge SHARD_OUT... -o OUT`: joins the outputs of `raylab
// grade --shard I/N` runs (graded on several machines, e.g. a Slurm job
// array) into one OUT whose grades.csv equals, byte for byte, that of an
// unsharded run. Refuses shards graded with different rubrics, a student
// graded twice, and a set of shards that misses a slice.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

namespace rl {

// Throws rl::Error naming the folder at fault.
void mergeGradeOutputs(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out,
                       std::ostream& log);

}  // namespace rl
