// The HTML report: OUT/index.html, a table of every student (sortable by
// clicking a header, failures highlighted), and OUT/<id>/index.html per
// student with, for every check scene of every exercise, their render, the
// reference and a difference heat map, plus the probe counts and the
// compile log. Self-contained: inline CSS and a few lines of inline
// JavaScript, relative links only, so it opens from the file system with
// no server and no network.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rl {

std::string classIndexPage(const Rubric& rubric, const std::vector<StudentGrade>& grades,
                           const nlohmann::json& summary);
std::string studentPage(const Rubric& rubric, const StudentGrade& grade);

std::string htmlEscape(const std::string& text);
// Percent-encodes one path segment for a relative URL ("a b" -> "a%20b").
std::string urlSegment(const std::string& text);

}  // namespace rl
