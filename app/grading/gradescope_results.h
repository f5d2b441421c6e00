// OUT/<id>/results.json in Gradescope's autograder format
// (https://gradescope-autograders.readthedocs.io/en/latest/specs/): the
// total as "score", one test per rubric exercise with its points, "passed"
// only for a PASS, and the checker's message, hint and log as its output.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

namespace rl {

nlohmann::json gradescopeResults(const Rubric& rubric, const StudentGrade& grade);

// The text a student reads about one exercise: status, reason, hint, log.
std::string exerciseFeedback(const ExerciseGrade& grade);

}  // namespace rl
