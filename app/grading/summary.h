// OUT/summary.json: what a run found, in numbers, for the instructor and
// for scripts (counts of exercise outcomes, students at full marks, time).
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
    std::vector<std::string> ignored; // entries of SUBMISSIONS that are no student
};

nlohmann::json gradeSummary(const Rubric& rubric, const std::vector<StudentGrade>& grades, const RunInfo& info);

}  // namespace rl
