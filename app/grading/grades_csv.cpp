#include "grading/grades_csv.h"

#include <algorithm>
#include <regex>

namespace rl {

bool startsLikeFormula(const std::string& text) {
    if (text.empty() || std::string("=+-@\t\r").find(text[0]) == std::string::npos) return false;
    static const std::regex number(R"(^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$)");
    return !std::regex_match(text, number);
}

std::string csvField(const std::string& text) {
    // Instructors open these files in a spreadsheet before they import them:
    // a cell that would start a formula gets a leading ' (OWASP's rule). The
    // columns the importers match students by are numbers (Canvas's ID) or
    // are checked by lms_export.cpp before they are written.
    const std::string cell = startsLikeFormula(text) ? "'" + text : text;
    if (cell.find_first_of(",;\"\r\n") == std::string::npos) return cell;
    std::string out = "\"";
    for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string gradesCsv(const Rubric& rubric, const std::vector<StudentGrade>& grades) {
    std::vector<const StudentGrade*> sorted;
    for (const StudentGrade& g : grades) sorted.push_back(&g);
    std::sort(sorted.begin(), sorted.end(), [](const StudentGrade* a, const StudentGrade* b) { return a->id < b->id; });
    std::string csv = csvField(rubric.idColumn);
    for (const RubricExercise& e : rubric.exercises) csv += "," + csvField(e.column);
    csv += "," + csvField(rubric.totalColumn) + "\n";
    for (const StudentGrade* g : sorted) {
        StudentScore s = scoreStudent(rubric, *g);
        csv += csvField(g->id);
        for (long h : s.hundredths) csv += "," + formatPoints(h);
        csv += "," + formatPoints(s.total) + "\n";
    }
    return csv;
}

}  // namespace rl
