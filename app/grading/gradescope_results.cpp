#include "grading/gradescope_results.h"

#include "course/exercise_registry.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

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

namespace {

// Lines that point at image files: Gradescope keeps only results.json, so
// they become the numbers of the images summary instead.
bool pointsAtAFile(const std::string& line) {
    for (const char* lead : {"    expected ", "    got      ", "    diff     "})
        if (line.rfind(lead, 0) == 0) return true;
    return false;
}

std::string imagesSummary(const ExerciseReport& r) {
    if (r.images.empty()) return "";
    int within = 0;
    for (const ImageSummary& i : r.images) within += i.passed;
    std::string text = "check images: " + std::to_string(within) + " of " + std::to_string(r.images.size()) +
                       " within the budget (at most 0.5% of pixels off by more than 1/255)\n";
    for (const ImageSummary& i : r.images) {
        char line[256];
        if (i.passed)
            std::snprintf(line, sizeof line, "  %s: within budget\n", i.scene.c_str());
        else
            std::snprintf(line, sizeof line, "  %s: %.2f%% of pixels off, mean error %.2f/255%s\n", i.scene.c_str(),
                          100 * i.offFraction, i.meanLsb,
                          i.nonFinite ? (", " + std::to_string(i.nonFinite) + " NaN/Inf values").c_str() : "");
        text += line;
    }
    return text;
}

std::string htmlEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            default: out += c;
        }
    }
    return out;
}

// The feedback of one exercise, everything inside results.json, in the rubric's output format.
std::string gradescopeFeedback(const ExerciseGrade& g, const std::string& format) {
    const ExerciseReport& r = g.report;
    std::string head = gradeStatus(g), body;
    if (r.status == CheckStatus::Pass && !g.refused) {
        head = exerciseFeedback(g);
        head.pop_back();
    } else {
        if (!r.message.empty()) head += ": " + r.message;
        std::string hint = r.hint;
        auto compare = hint.find("compare ");
        if (compare != std::string::npos && !r.images.empty())
            hint = hint.substr(0, compare) + "compare your render with the reference on your report page";
        if (!hint.empty()) head += "\nhint: " + hint;
        std::istringstream lines(r.details);
        for (std::string line; std::getline(lines, line);)
            if (!pointsAtAFile(line)) body += line + "\n";
    }
    std::string images = r.status == CheckStatus::Pass ? "" : imagesSummary(r);
    if (format == "md") {
        std::string out;
        std::istringstream lines(head);
        for (std::string line; std::getline(lines, line);) out += line + "\n\n";
        if (!body.empty()) out += "```\n" + body + "```\n";
        if (!images.empty()) out += "\n```\n" + images + "```\n";
        return out;
    }
    if (format == "html") {
        std::string out = "<p>" + htmlEscaped(head) + "</p>\n";
        if (!body.empty() || !images.empty()) out += "<pre>" + htmlEscaped(body + images) + "</pre>\n";
        return out;
    }
    return head + "\n" + (body.empty() ? "" : "\n" + body) + (images.empty() ? "" : "\n" + images);
}

}  // namespace

json gradescopeResults(const Rubric& rubric, const StudentGrade& g) {
    StudentScore score = scoreStudent(rubric, g);
    const GradescopeSettings& gs = rubric.gradescope;
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
                         {"output", x ? gradescopeFeedback(*x, gs.outputFormat) : "NOT STARTED: not graded\n"},
                         {"output_format", gs.outputFormat},
                         {"visibility", e.visibility}});
    }
    std::string output;
    for (const std::string& note : g.notes) output += (gs.outputFormat == "md" ? "- " : "") + note + "\n";
    if (gs.outputFormat == "html") output = output.empty() ? "" : "<pre>" + htmlEscaped(output) + "</pre>\n";
    json j = {{"score", double(score.total) / 100.0},
              {"execution_time", int(std::ceil(g.seconds))},
              {"output_format", gs.outputFormat},
              {"test_output_format", gs.outputFormat},
              {"visibility", gs.visibility},
              {"stdout_visibility", gs.stdoutVisibility},
              {"tests", tests}};
    if (!output.empty()) j["output"] = output;
    if (gs.leaderboard)
        j["leaderboard"] = json::array({{{"name", "Total"}, {"value", double(score.total) / 100.0}, {"order", "desc"}}});
    return j;
}

}  // namespace rl
