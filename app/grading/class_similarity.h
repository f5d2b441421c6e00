// The similarity section of a class's outputs (grading/similarity.h) from
// the graded copies in OUT/<id>/submission/, with the course's stub and,
// where the repository has it, its solution as base code. The same for an
// unsharded run and for `grade merge` of its slices.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <vector>

namespace rl {

nlohmann::json classSimilarity(const std::filesystem::path& out, const Rubric& rubric,
                               const std::vector<StudentGrade>& grades);

}  // namespace rl
