#include "grading/grades_csv.h"

#include <algorithm>

namespace rl {

std::string csvField(const std::string& text) {
    // Ids are written as they are (an LMS matches them exactly), never
    // rewritten against spreadsheet formulas: import the file, do not open it.
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
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
