// OUT/grades.csv: one header row, then one row per student sorted by id,
// the id first, points per exercise, the total last, every number with two
// decimals (the id column's header comes from the rubric or --id-column);
// same records, same bytes. For reading and scripts: the files Canvas and
// Moodle import are grading/lms_export.h's.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <string>
#include <vector>

namespace rl {

std::string gradesCsv(const Rubric& rubric, const std::vector<StudentGrade>& grades);

// RFC 4180 quoting, only where needed.
std::string csvField(const std::string& text);

}  // namespace rl
