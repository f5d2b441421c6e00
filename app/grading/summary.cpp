#include "grading/summary.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace rl {

using nlohmann::json;

namespace {
// Names listed in summary.json (and the report) per list; the counts are whole.
constexpr std::size_t kListedEntries = 100;
}  // namespace

json classMistakes(const Rubric& rubric, const std::vector<StudentGrade>& grades) {
    json all = json::array();
    // Most students first, then by text, so that the same class gives the same bytes.
    auto sorted = [](const std::map<std::string, int>& counts, const char* key) {
        std::vector<std::pair<std::string, int>> v(counts.begin(), counts.end());
        std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
        json out = json::array();
        for (const auto& [text, n] : v) out.push_back({{key, text}, {"students", n}});
        return out;
    };
    for (const RubricExercise& e : rubric.exercises) {
        std::map<std::string, int> hints, probes, statuses;
        int passed = 0;
        for (const StudentGrade& g : grades) {
            const ExerciseGrade* x = g.find(e.id);
            const std::string status = x ? gradeStatus(*x) : "NOT STARTED";
            if (status == "PASS") {
                ++passed;
                continue;
            }
            ++statuses[status];
            if (!x) continue;
            // The checker's hint names a recognised mistake; a stub or a refusal is no mistake in the shader.
            if (!x->report.hint.empty() && status != "NOT STARTED" && status != "REFUSED") ++hints[x->report.hint];
            for (const ProbeSummary& p : x->report.probes)
                if (p.passed < p.total) ++probes[p.name];
        }
        all.push_back({{"exercise", e.id},
                       {"passed", passed},
                       {"not_passed", sorted(statuses, "status")},
                       {"hints", sorted(hints, "hint")},
                       {"failed_probe_groups", sorted(probes, "probe_group")}});
    }
    return all;
}

std::string reasonOf(const std::string& entry) {
    // "name (reason)": the reason is the last parenthesis; a name may hold parentheses too.
    const std::size_t open = entry.rfind(" (");
    if (open == std::string::npos || entry.empty() || entry.back() != ')') return "other";
    return entry.substr(open + 2, entry.size() - open - 3);
}

json byReason(const std::vector<std::string>& entries) {
    std::map<std::string, int> counts;
    for (const std::string& e : entries) ++counts[reasonOf(e)];
    json out = json::array();
    for (const auto& [reason, n] : counts) out.push_back({{"reason", reason}, {"count", n}});
    return out;
}

json firstFew(const std::vector<std::string>& entries) {
    std::vector<std::string> some(entries.begin(), entries.begin() + std::ptrdiff_t(std::min<std::size_t>(entries.size(), kListedEntries)));
    return some;
}

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
    // Bounded: 10,000 junk files beside the students are counts by reason and the first few names.
    j["ignored_count"] = info.ignored.size();
    j["ignored_by_reason"] = byReason(info.ignored);
    j["ignored_entries"] = firstFew(info.ignored);
    j["roster_without_submission"] = firstFew(info.rosterWithoutSubmission);
    j["roster_without_submission_count"] = info.rosterWithoutSubmission.size();
    j["submissions_without_roster_student"] = firstFew(info.unmatchedSubmissions);
    j["submissions_without_roster_student_count"] = info.unmatchedSubmissions.size();
    j["class_mistakes"] = classMistakes(rubric, grades);
    j["students_file"] = "students.txt";
    return j;
}

}  // namespace rl
