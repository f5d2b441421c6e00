// What grading found for one student: the checker's report for each
// exercise of the rubric, and what happened to the submission before any
// check ran (refused files, a corrupt zip, an empty folder). Points are not
// stored here: they follow from these reports and the rubric
// (grading/rubric.h), so a changed rubric re-scores without re-running.
// Saved as OUT/<id>/grade.json; its presence marks the student as graded.
#pragma once

#include "checks/checker.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rl {

struct ExerciseGrade {
    ExerciseReport report;  // the checker's verdict; for a refused file, COMPILE ERROR with the reason
    bool refused = false;   // refused before checking (symlink, size, encoding, unsafe zip)
};

// The status shown to students: the checker's status name, or "REFUSED".
std::string gradeStatus(const ExerciseGrade& grade);

struct StudentGrade {
    std::string id;                        // the entry's name in SUBMISSIONS ("alice" for alice.zip)
    std::string source;                    // that entry ("alice.zip"), escaped when not plain UTF-8 (grading/entry_name.h)
    std::string sourceBytes;               // the entry's name as bytes (hex) when `source` is escaped; else ""
    std::string fingerprint;               // submissionFingerprint() of what was graded
    std::vector<std::string> notes;        // about the whole submission: ignored files, nesting, refusals
    std::vector<ExerciseGrade> exercises;  // in rubric order
    double seconds = 0;                    // wall-clock time grading took
    bool complete = true;                  // false when the grader itself failed: regraded on the next run

    const ExerciseGrade* find(const std::string& exerciseId) const;
};

nlohmann::json toJson(const StudentGrade& grade);
StudentGrade studentGradeFromJson(const nlohmann::json& j);

// OUT/<id>/ and OUT/<id>/grade.json.
std::filesystem::path studentDir(const std::filesystem::path& out, const std::string& id);
std::filesystem::path gradeRecordPath(const std::filesystem::path& out, const std::string& id);

// The record of a student, or nullopt when there is none or it cannot be
// parsed (an interrupted write leaves no record: see atomic_file.h).
std::optional<StudentGrade> loadStudentGrade(const std::filesystem::path& out, const std::string& id);
void saveStudentGrade(const std::filesystem::path& out, const StudentGrade& grade);

}  // namespace rl
