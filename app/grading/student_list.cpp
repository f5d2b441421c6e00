#include "grading/student_list.h"

#include "core/error.h"
#include "grading/atomic_file.h"
#include "grading/entry_name.h"

#include <fstream>

namespace fs = std::filesystem;

namespace rl {

fs::path studentListPath(const fs::path& out) { return out / "students.txt"; }

void writeStudentList(const fs::path& out, const std::vector<std::string>& ids) {
    std::string text;
    for (const std::string& id : ids) text += id + "\n";
    writeOutputFile(studentListPath(out), text);
}

std::vector<std::string> readStudentList(const fs::path& out) {
    const fs::path path = studentListPath(out);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(path.string() + ": missing (is this the output of `raylab grade`, and did it finish?)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot read");
    std::vector<std::string> ids;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.empty() || line.size() > 4 * kMaxEntryIdBytes || !isPlainUtf8(line) ||
            line.find('/') != std::string::npos || line == "." || line == "..")
            throw Error(path.string() + ":" + std::to_string(n) + ": not a student id");
        ids.push_back(line);
    }
    return ids;
}

}  // namespace rl
