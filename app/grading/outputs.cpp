#include "grading/outputs.h"

#include "core/error.h"
#include "core/image.h"
#include "grading/atomic_file.h"
#include "grading/grades_csv.h"
#include "grading/gradescope_results.h"
#include "grading/html_report.h"
#include "grading/student_list.h"

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace rl {

std::string referenceImagePath(const std::string& scene) { return "_reference/" + scene + ".png"; }

void writeReferenceImages(const fs::path& out, const std::vector<CheckScene>& scenes) {
    std::error_code ec;
    fs::create_directories(out / "_reference", ec);
    for (const CheckScene& c : scenes) {
        // writePng is atomic: a concurrent shard or reader never sees half a PNG.
        writePng((out / referenceImagePath(c.name)).string(), c.reference.display);
    }
}

void writeStudentOutputs(const fs::path& out, const Rubric& rubric, const StudentGrade& grade) {
    fs::path dir = studentDir(out, grade.id);
    writeOutputFile(dir / "results.json", gradescopeResults(rubric, grade).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    writeOutputFile(dir / "index.html", studentPage(rubric, grade));
}

std::vector<std::string> writeClassOutputs(const fs::path& out, const Rubric& rubric,
                                           const std::vector<StudentGrade>& grades, nlohmann::json summary) {
    std::vector<std::string> failed, ids;
    for (const StudentGrade& g : grades) {
        ids.push_back(g.id);
        try {
            writeStudentOutputs(out, rubric, g);
        } catch (const std::exception& e) {
            failed.push_back(e.what());
        }
    }
    summary["students_not_written"] = failed;
    writeStudentList(out, ids);
    writeOutputFile(out / "rubric.json", toJson(rubric).dump(2) + "\n");
    writeOutputFile(out / "grades.csv", gradesCsv(rubric, grades));
    writeOutputFile(out / "summary.json", summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    writeOutputFile(out / "index.html", classIndexPage(rubric, grades, summary));
    return failed;
}

}  // namespace rl
