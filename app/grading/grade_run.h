// A grading run: which students of SUBMISSIONS this run grades (a shard of
// them), each in its own worker process, `jobs` at a time, and the class
// outputs at the end (grading/outputs.h).
//
// Process layout. The parent computes the check scenes (whose CPU reference
// uses threads, all joined) before starting workers, and never creates a GL
// context. The workers are a pool of child processes (core/process_pool.h:
// the only place that starts, limits, signals and waits for them). A worker
// grades one student: it stages the submission, then checks each exercise
// with checkExercise, which runs it in one more child process with a
// wall-clock timeout and a memory limit (core/isolated.h). A worker past its
// deadline is told (SIGTERM: it kills the check it waits for) and killed 2 s
// later; it gets an RLIMIT_CPU that its checks inherit, so even a check
// orphaned by a worker killed otherwise ends on its own. Ctrl-C stops the
// checks in progress at once.
// Each worker writes OUT/<id>/grade.json atomically when it is done: an
// interrupted run keeps every finished student, and the next run skips them.
#pragma once

#include "checks/checker.h"
#include "grading/rubric.h"
#include "grading/student_grade.h"
#include "grading/submission.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rl {

struct GradeSettings {
    std::filesystem::path out;    // OUT
    Rubric rubric;
    double timeoutSeconds = 30;   // per exercise
    int jobs = 1;                 // students graded at the same time
    bool force = false;           // regrade students that already have a complete record
    std::string backend = "auto";
};

struct GradeBatch {
    int graded = 0;           // students graded by this run
    int skipped = 0;          // already graded in OUT
    int failed = 0;           // the grader itself failed for them (recorded incomplete)
    bool interrupted = false; // SIGINT/SIGTERM: finished students are kept
};

// Grades every entry that has no complete, current record for the rubric in
// OUT (all of them with `force`), writing OUT/<id>/ for each; prints one progress
// line per student on `progress`. Throws rl::Error only for problems of the
// run itself (OUT cannot be written), never for a submission.
GradeBatch gradeStudents(const std::vector<SubmissionEntry>& entries, const GradeSettings& settings,
                         std::ostream& progress);

// Grades one student in the calling process (a worker) and returns the
// record; writes the staged copy and images under OUT/<id>/ but not the record.
StudentGrade gradeStudent(const SubmissionEntry& entry, const GradeSettings& settings,
                          const std::vector<CheckScene>& scenes);

// Whether OUT holds a complete record of this entry, of the submission as it
// is now (its fingerprint), covering every rubric exercise.
bool alreadyGraded(const std::filesystem::path& out, const SubmissionEntry& entry, const Rubric& rubric);

// The slice of students a shard grades: FNV-1a of the id, modulo the count.
// Stable across machines and runs, and a late submission moves no one else.
int shardOf(const std::string& id, int shardCount);  // 1..shardCount

// `raylab grade SUBMISSIONS -o OUT`: lists, shards, grades, writes the class
// outputs. Returns the process exit status (0, or 130 when interrupted).
struct GradeRunOptions {
    std::filesystem::path submissions;
    GradeSettings settings;
    int shardIndex = 1, shardCount = 1;  // --shard I/N
    std::filesystem::path roster;        // --roster: its students without a submission go into the report
};
int runGrade(const GradeRunOptions& options, std::ostream& log);

// `raylab grade --gradescope`: ROOT/submission in, ROOT/results/results.json
// out (ROOT is /autograder in Gradescope's container). Always writes a
// results.json, with the reason, when it returns.
int runGradescope(const std::filesystem::path& root, GradeSettings settings, std::ostream& log);

}  // namespace rl
