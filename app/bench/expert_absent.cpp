// The expert yardstick in a student edition: its generator (expert.cpp,
// expert_scene.cpp) writes the model fused into one shader, every exercise's
// answer among it, so scripts/student-edition.sh leaves it out and the bench
// skips its row, saying why (docs/instructor.md, "A student edition").
#include "bench/expert.h"

#include "core/error.h"

namespace rl::bench {

namespace {
const char* const kAbsent =
    "not in this copy: a student edition leaves the expert yardstick out (its generator writes the model)";
}

std::string expertUnsupported(const Scene&) { return kAbsent; }
std::string expertFragmentSource(const Scene&) { throw Error(kAbsent); }
ShaderProgram buildExpert(const Scene&) { throw Error(kAbsent); }

}  // namespace rl::bench
