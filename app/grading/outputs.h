// Everything a run writes into OUT, from the per-student records:
//   OUT/<id>/results.json   Gradescope's format (grading/gradescope_results.h)
//   OUT/<id>/index.html     the student's page (grading/html_report.h)
//   OUT/grades.csv          (grading/grades_csv.h)
//   OUT/index.html          the class table
//   OUT/summary.json        (grading/summary.h): counts, bounded for any class
//   OUT/students.txt        the students' ids (grading/student_list.h)
//   OUT/rubric.json         the rubric the points come from
//   OUT/_reference/*.png    the check scenes' references, shared by all pages
// Every file is written atomically (grading/atomic_file.h).
#pragma once

#include "checks/checker.h"
#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

// "_reference/<scene>.png", relative to OUT.
std::string referenceImagePath(const std::string& scene);
void writeReferenceImages(const std::filesystem::path& out, const std::vector<CheckScene>& scenes);

void writeStudentOutputs(const std::filesystem::path& out, const Rubric& rubric, const StudentGrade& grade);

// The class files, and every student's own files again, so that all of
// them follow the same rubric. A student whose files cannot be written is
// left out of nothing else: the reasons are returned ("path: cannot write
// (why)") and listed in summary.json's "students_not_written".
std::vector<std::string> writeClassOutputs(const std::filesystem::path& out, const Rubric& rubric,
                                           const std::vector<StudentGrade>& grades, nlohmann::json summary);

}  // namespace rl
