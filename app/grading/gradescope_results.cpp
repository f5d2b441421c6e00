#include "grading/gradescope_results.h"

#include "checks/exercise_registry.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace rl {

using nlohmann::json;

std::string exerciseFeedback(const ExerciseGrade& g) {
    const ExerciseReport& r = g.report;
    std::string text = gradeStatus(g);
    if (r.status == CheckStatus::Pass && !g.refused) {
        int cases = 0;
        for (const ProbeSummary& p : r.probes) cases += p.total;
        return text + ": " + std::to_string(cases) + " probe cases and " + std::to_string(r.images.size()) +
               " check images agree with the reference\n";
    }
    if (!r.message.empty()) text += ": " + r.message;
    text += "\n";
    if (!r.hint.empty()) text += "hint: " + r.hint + "\n";
    if (!r.details.empty()) text += "\n" + r.details;
    return text;
}

json gradescopeResults(const Rubric& rubric, const StudentGrade& g) {
    StudentScore score = scoreStudent(rubric, g);
    json tests = json::array();
    for (std::size_t k = 0; k < rubric.exercises.size(); ++k) {
        const RubricExercise& e = rubric.exercises[k];
        const ExerciseInfo& info = findExercise(e.id);
        const ExerciseGrade* x = g.find(e.id);
        bool passed = x && !x->refused && x->report.status == CheckStatus::Pass;
        tests.push_back({{"name", e.id + ": " + info.title},
                         {"number", std::to_string(info.number)},
                         {"score", double(score.hundredths[k]) / 100.0},
                         {"max_score", std::round(e.weight * 100.0) / 100.0},
                         {"status", passed ? "passed" : "failed"},
                         {"output", x ? exerciseFeedback(*x) : "NOT STARTED: not graded\n"},
                         {"visibility", "visible"}});
    }
    std::string output;
    for (const std::string& note : g.notes) output += note + "\n";
    json j = {{"score", double(score.total) / 100.0},
              {"execution_time", int(std::ceil(g.seconds))},
              {"visibility", "visible"},
              {"tests", tests}};
    if (!output.empty()) j["output"] = output;
    return j;
}

}  // namespace rl
