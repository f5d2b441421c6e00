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

// Whether a spreadsheet would read the cell as a formula (OWASP's CSV
// injection rule): it starts with '=', '+', '-', '@', a tab or a carriage
// return, and is not a plain number ("-1.5" stays a number).
bool startsLikeFormula(const std::string& text);

// RFC 4180 quoting, only where needed; a cell that startsLikeFormula gets a
// leading ' first, so that no spreadsheet runs it (docs/decisions.md).
std::string csvField(const std::string& text);

}  // namespace rl
