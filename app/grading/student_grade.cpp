#include "grading/student_grade.h"

#include "core/json_text.h"
#include "grading/atomic_file.h"

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace rl {

using nlohmann::json;

std::string gradeStatus(const ExerciseGrade& grade) {
    return grade.refused ? "REFUSED" : statusName(grade.report.status);
}

const ExerciseGrade* StudentGrade::find(const std::string& exerciseId) const {
    for (const ExerciseGrade& e : exercises)
        if (e.report.id == exerciseId) return &e;
    return nullptr;
}

json toJson(const StudentGrade& g) {
    json exercises = json::array();
    for (const ExerciseGrade& e : g.exercises) {
        json r = toJson(e.report);
        r["refused"] = e.refused;
        exercises.push_back(r);
    }
    json j = {{"id", g.id},         {"source", g.source},     {"fingerprint", g.fingerprint}, {"notes", g.notes},
              {"seconds", g.seconds}, {"complete", g.complete}, {"exercises", exercises}};
    if (!g.sourceBytes.empty()) j["source_bytes"] = g.sourceBytes;
    return j;
}

StudentGrade studentGradeFromJson(const json& j) {
    StudentGrade g;
    g.id = j.at("id").get<std::string>();
    g.source = j.value("source", "");
    g.sourceBytes = j.value("source_bytes", "");
    g.fingerprint = j.value("fingerprint", "");
    g.notes = j.value("notes", std::vector<std::string>{});
    g.seconds = j.value("seconds", 0.0);
    g.complete = j.value("complete", false);
    for (const json& r : j.at("exercises")) g.exercises.push_back({reportFromJson(r), r.value("refused", false)});
    return g;
}

fs::path studentDir(const fs::path& out, const std::string& id) { return out / id; }

fs::path gradeRecordPath(const fs::path& out, const std::string& id) { return studentDir(out, id) / "grade.json"; }

std::optional<StudentGrade> loadStudentGrade(const fs::path& out, const std::string& id) {
    std::error_code ec;
    fs::path path = gradeRecordPath(out, id);
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    try {
        StudentGrade g = studentGradeFromJson(parseJsonText(readWholeFile(path), path.string()));
        if (g.id != id) return std::nullopt;
        return g;
    } catch (const std::exception&) {  // unreadable or not a record: grade again
        return std::nullopt;
    }
}

void saveStudentGrade(const fs::path& out, const StudentGrade& grade) {
    writeOutputFile(gradeRecordPath(out, grade.id), toJson(grade).dump(1, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace rl
