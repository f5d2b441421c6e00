// OUT/summary.json: what a run found, in numbers, for the instructor and
// for scripts (counts of exercise outcomes, students at full marks, time).
// Bounded for any class: the students' ids are in OUT/students.txt, their
// records in OUT/<id>/, and every list here is cut to its first 100 with
// the whole count beside it.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rl {

struct RunInfo {
    double seconds = 0;               // wall-clock time of the whole run
    int graded = 0, skipped = 0;      // by this run / already in OUT
    int jobs = 1;
    double timeoutSeconds = 0;
    int shardIndex = 1, shardCount = 1;
    std::size_t submissionsTotal = 0; // students in SUBMISSIONS, all shards
    std::vector<std::string> ignored; // entries of SUBMISSIONS that are no student, with the reason
    std::vector<std::string> rosterWithoutSubmission;  // with --roster: "Name (roster.csv line N)"
    std::vector<std::string> unmatchedSubmissions;     // with --roster: "id: why no student matches"
};

// What the class got wrong, per rubric exercise: how many students made each
// mistake the checker recognised (its hint) and failed each probe group,
// most students first (summary.json's "class_mistakes", the report's table).
nlohmann::json classMistakes(const Rubric& rubric, const std::vector<StudentGrade>& grades);

// "name (reason)" -> "reason", for the Not-graded counts.
std::string reasonOf(const std::string& ignoredEntry);
nlohmann::json byReason(const std::vector<std::string>& ignoredEntries);
nlohmann::json firstFew(const std::vector<std::string>& entries);

nlohmann::json gradeSummary(const Rubric& rubric, const std::vector<StudentGrade>& grades, const RunInfo& info);

}  // namespace rl
