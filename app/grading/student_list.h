// OUT/students.txt: the ids of a run's students, one a line, sorted. What
// `grade export` and `grade merge` read to find the records (OUT/<id>/
// grade.json), line by line, so that neither depends on a file growing
// with the class: summary.json holds counts, not the class.
// An id holds no control character (grading/entry_name.h), so a line is an id.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

std::filesystem::path studentListPath(const std::filesystem::path& out);
void writeStudentList(const std::filesystem::path& out, const std::vector<std::string>& ids);
// Throws rl::Error naming the file when it is missing or holds a line that is no id.
std::vector<std::string> readStudentList(const std::filesystem::path& out);

}  // namespace rl
