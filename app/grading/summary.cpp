#include "grading/summary.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>

namespace rl {

using nlohmann::json;

json gradeSummary(const Rubric& rubric, const std::vector<StudentGrade>& grades, const RunInfo& info) {
    // Every status, always present, so that scripts need no defaults.
    std::map<std::string, int> outcomes = {{"PASS", 0},          {"FAIL", 0},    {"NOT STARTED", 0}, {"COMPILE ERROR", 0},
                                           {"TIMEOUT", 0},       {"CRASH", 0},   {"REFUSED", 0}};
    long totalSum = 0;
    int fullMarks = 0, zero = 0, incomplete = 0;
    for (const StudentGrade& g : grades) {
        for (const RubricExercise& e : rubric.exercises) {
            const ExerciseGrade* x = g.find(e.id);
            ++outcomes[x ? gradeStatus(*x) : "NOT STARTED"];
        }
        StudentScore s = scoreStudent(rubric, g);
        totalSum += s.total;
        fullMarks += s.total == rubric.maxHundredths();
        zero += s.total == 0;
        incomplete += !g.complete;
    }
    double mean = grades.empty() ? 0.0 : double(totalSum) / 100.0 / double(grades.size());
    json j;
    j["students"] = grades.size();
    j["graded_this_run"] = info.graded;
    j["skipped_already_graded"] = info.skipped;
    j["grader_failures"] = incomplete;
    j["exercise_outcomes"] = outcomes;
    j["passes"] = outcomes["PASS"];
    j["failures"] = outcomes["FAIL"];
    j["not_started"] = outcomes["NOT STARTED"];
    j["compile_errors"] = outcomes["COMPILE ERROR"];
    j["timeouts"] = outcomes["TIMEOUT"];
    j["crashes"] = outcomes["CRASH"];
    j["refused"] = outcomes["REFUSED"];
    j["full_marks"] = fullMarks;
    j["zero_marks"] = zero;
    j["mean_total"] = std::round(mean * 100.0) / 100.0;
    j["max_total"] = double(rubric.maxHundredths()) / 100.0;
    j["seconds"] = std::round(info.seconds * 10.0) / 10.0;
    j["jobs"] = info.jobs;
    j["timeout_seconds"] = info.timeoutSeconds;
    j["shard"] = {{"index", info.shardIndex}, {"count", info.shardCount}};
    j["submissions_total"] = info.submissionsTotal;
    j["ignored_entries"] = info.ignored;
    json ids = json::array();
    for (const StudentGrade& g : grades) ids.push_back(g.id);
    j["student_ids"] = ids;
    return j;
}

}  // namespace rl
