#include "grading/grade_run.h"

#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/message.h"
#include "core/process_pool.h"
#include "grading/atomic_file.h"
#include "grading/entry_name.h"
#include "grading/lms_export.h"
#include "grading/outputs.h"
#include "grading/class_similarity.h"
#include "grading/summary.h"
#include "shader/source_assembler.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <thread>

namespace fs = std::filesystem;

namespace rl {

namespace {

using Clock = std::chrono::steady_clock;

// Thrown in a worker when Ctrl-C or SIGTERM arrived (core/process_pool.h):
// the student is left without a record and graded again by the next run.
struct Interrupted {};

unsigned cpuCount() {
    unsigned n = std::thread::hardware_concurrency();  // the online processors, as sysconf says
    return n > 0 ? n : 1u;
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t pos = 0; (pos = text.find(from, pos)) != std::string::npos; pos += to.size())
        text.replace(pos, from.size(), to);
}

// Makes a report about OUT/<id>/ read as if about the student's own folder:
// "05-ggx.glsl:12: ..." rather than the instructor's paths, and image paths
// relative to OUT/<id>/ (the check scenes' references are shared in
// OUT/_reference/, so each student's copy of them is dropped).
void tidyReport(ExerciseReport& report, const fs::path& dir) {
    std::error_code ec;
    for (ImageSummary& image : report.images) {
        if (!image.expectedPng.empty()) {
            fs::remove(image.expectedPng, ec);
            std::string shared = "../" + referenceImagePath(image.scene);
            for (std::string* text : {&report.message, &report.hint, &report.details})
                replaceAll(*text, image.expectedPng, shared);
            image.expectedPng = shared;
        }
    }
    const fs::path staged = dir / "submission";
    std::vector<std::string> prefixes = {displayPath(staged), staged.string(), fs::absolute(staged, ec).string(),
                                         displayPath(dir), dir.string(), fs::absolute(dir, ec).string()};
    for (std::string& prefix : prefixes) prefix += "/";
    // Longest first, so that OUT/<id>/submission/ goes before OUT/<id>/.
    std::stable_sort(prefixes.begin(), prefixes.end(),
                     [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
    for (std::string* text : {&report.message, &report.hint, &report.details})
        for (const std::string& prefix : prefixes) {
            // The include resolver's "the file lies outside DIR/" names the student's own folder.
            replaceAll(*text, "outside " + prefix + "\n", "outside your submission folder\n");
            if (text->size() >= prefix.size() + 8 && text->compare(text->size() - prefix.size() - 8, std::string::npos,
                                                                   "outside " + prefix) == 0)
                text->replace(text->size() - prefix.size(), prefix.size(), "your submission folder");
            replaceAll(*text, prefix, "");
        }
    for (ImageSummary& image : report.images)
        for (std::string* path : {&image.gotPng, &image.diffPng})
            for (const std::string& prefix : prefixes)
                if (path->compare(0, prefix.size(), prefix) == 0) *path = path->substr(prefix.size());
}

ExerciseReport reportWithReason(const ExerciseInfo& info, CheckStatus status, const std::string& message,
                                const std::string& hint) {
    ExerciseReport r;
    r.number = info.number;
    r.id = info.id;
    r.status = status;
    r.message = message;
    r.hint = hint;
    return r;
}

// Where the record says the student's work came from: the entry's name, as
// a safe string, with its bytes kept when they had to be escaped.
void setSource(StudentGrade& g, const SubmissionEntry& entry) {
    const std::string raw = entry.path.filename().string();
    g.source = escapedName(raw);  // whole: the roster and the exports read the LMS's name in it
    g.sourceBytes = g.source == raw ? "" : hexBytes(raw);
}

// The record of a student whose worker died or hung: kept so that the
// student appears in every output with the reason, and regraded next time.
StudentGrade failedRecord(const SubmissionEntry& entry, const Rubric& rubric, const std::string& why) {
    StudentGrade g;
    g.id = entry.id;
    setSource(g, entry);
    g.complete = false;
    g.notes.push_back("the grader itself failed for this submission (" + why +
                      "); it is graded again on the next run");
    for (const RubricExercise& e : rubric.exercises)
        g.exercises.push_back({reportWithReason(findExercise(e.id), CheckStatus::Crashed, "not graded: " + why,
                                                "ask the instructor to run the grader again"),
                               false});
    return g;
}

// Runs in the worker: grades, then writes the student's outputs. Its end
// tells the run how it went: "" (the record is in OUT), ChildExit 130
// (interrupted), ChildExit 2 (the grader failed, said on stderr).
std::string workerMain(const SubmissionEntry& entry, const GradeSettings& settings,
                       const std::vector<CheckScene>& scenes) {
    try {
        StudentGrade grade = gradeStudent(entry, settings, scenes);
        saveStudentGrade(settings.out, grade);
        writeStudentOutputs(settings.out, settings.rubric, grade);
        return "";
    } catch (const Interrupted&) {
        throw ChildExit{130};
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: grading %s: %s\n", entry.id.c_str(), e.what());
        throw ChildExit{2};
    }
}

}  // namespace

bool alreadyGraded(const fs::path& out, const SubmissionEntry& entry, const Rubric& rubric) {
    std::optional<StudentGrade> g = loadStudentGrade(out, entry.id);
    if (!g || !g->complete || g->fingerprint != submissionFingerprint(entry)) return false;
    for (const RubricExercise& e : rubric.exercises)
        if (!g->find(e.id)) return false;
    return true;
}

int shardOf(const std::string& id, int shardCount) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bit
    for (unsigned char c : id) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return int(h % std::uint64_t(std::max(1, shardCount))) + 1;
}

StudentGrade gradeStudent(const SubmissionEntry& entry, const GradeSettings& settings,
                          const std::vector<CheckScene>& scenes) {
    auto start = Clock::now();
    const fs::path dir = studentDir(settings.out, entry.id);
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string() + ": cannot create (" + ec.message() + ")");

    StudentGrade grade;
    grade.id = entry.id;
    setSource(grade, entry);
    grade.fingerprint = submissionFingerprint(entry);
    StagedSubmission staged = stageSubmission(entry, dir / "submission", dir / ".unzip");
    grade.notes = staged.notes;
    if (!grade.sourceBytes.empty())
        grade.notes.insert(grade.notes.begin(), "the name of this submission is not plain UTF-8 text (bytes " +
                                                    grade.sourceBytes + "): graded as " + grade.id);
    else if (entry.kind != SubmissionEntry::Kind::Group && grade.source.size() > kMaxEntryIdBytes)
        grade.notes.insert(grade.notes.begin(), "the name of this submission has " +
                                                    std::to_string(grade.source.size()) + " bytes, more than an id may have (" +
                                                    std::to_string(kMaxEntryIdBytes) + "): graded as " + grade.id);
    if (staged.problem != StagedSubmission::Problem::None) grade.notes.insert(grade.notes.begin(), staged.problemReason);

    CheckOptions options;
    options.implDir = dir / "submission";
    options.outputDir = dir / "images";
    options.writeAllImages = true;
    options.writeExpectedImages = false;  // OUT/_reference/ holds them (tidyReport() points there)
    options.timeoutSeconds = settings.timeoutSeconds;
    options.backend = settings.backend;
    options.isolate = true;
    // The exercises a check runs for share one child process (checkExercises(),
    // falling back to one child each when it fails): their reports first.
    std::vector<const ExerciseInfo*> toCheck;
    for (const RubricExercise& r : settings.rubric.exercises) {
        const ExerciseInfo& info = findExercise(r.id);
        if (staged.problem == StagedSubmission::Problem::None && !staged.endless.count(info.file()) &&
            !staged.refused.count(info.file()))
            toCheck.push_back(&info);
    }
    if (interruptRequested()) throw Interrupted{};
    std::vector<ExerciseReport> checked = checkExercises(toCheck, options, scenes);
    if (interruptRequested()) throw Interrupted{};  // a check was cut short: not a verdict
    std::size_t next = 0;
    for (const RubricExercise& r : settings.rubric.exercises) {
        if (interruptRequested()) throw Interrupted{};
        const ExerciseInfo& info = findExercise(r.id);
        ExerciseGrade e;
        auto refused = staged.refused.find(info.file());
        if (staged.problem == StagedSubmission::Problem::Empty) {
            e.report = reportWithReason(info, CheckStatus::NotStarted, staged.problemReason,
                                        "submit your exercise files: a copy of exercises/, or a zip of it");
        } else if (staged.problem == StagedSubmission::Problem::Refused) {
            e.refused = true;
            e.report = reportWithReason(info, CheckStatus::CompileError, staged.problemReason,
                                        "submit a plain folder or .zip holding your exercise files");
        } else if (staged.endless.count(info.file())) {
            e.report = reportWithReason(info, CheckStatus::TimedOut, staged.endless.at(info.file()),
                                        "every loop needs a condition that becomes false, or a break");
        } else if (refused != staged.refused.end()) {
            e.refused = true;
            e.report = reportWithReason(info, CheckStatus::CompileError, refused->second,
                                        "submit " + info.file() + " as a plain UTF-8 text file inside your folder");
        } else {
            e.report = checked.at(next++);
            tidyReport(e.report, dir);
        }
        grade.exercises.push_back(e);
    }
    grade.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return grade;
}

// The run's own shader cache: Mesa's on-disk cache in OUT/.shader-cache
// (unless the user set MESA_SHADER_CACHE_DIR or turned the cache off), so a
// resumed or repeated run and byte-identical files reuse compiled shaders,
// and nothing is written to $HOME (read-only or shared on cluster nodes).
// It cannot carry one student's results to another: the key of an entry is a
// SHA-1 of the complete shader source (every exercise file and #define in it)
// with the driver's build, so an entry is found only for a byte-identical
// program, and what it holds is compiled code, never a result: every check
// still runs its probes and renders its scenes.
static void useRunShaderCache(const fs::path& out) {
    if (std::getenv("MESA_SHADER_CACHE_DIR") || std::getenv("MESA_SHADER_CACHE_DISABLE")) return;
    std::error_code ec;
    fs::create_directories(out / ".shader-cache", ec);
    if (!ec) setenv("MESA_SHADER_CACHE_DIR", fs::absolute(out / ".shader-cache").c_str(), 1);
}

GradeBatch gradeStudents(const std::vector<SubmissionEntry>& entries, const GradeSettings& settings,
                         std::ostream& progress) {
    GradeBatch batch;
    std::vector<const SubmissionEntry*> todo;
    for (const SubmissionEntry& e : entries) {
        if (!settings.force && alreadyGraded(settings.out, e, settings.rubric))
            ++batch.skipped;
        else
            todo.push_back(&e);
    }
    if (batch.skipped)
        progress << batch.skipped << " student" << (batch.skipped == 1 ? "" : "s")
                 << " already graded in " << settings.out.string() << " (--force grades them again)\n";
    std::error_code ec;
    bool haveReferences = fs::is_directory(settings.out / "_reference", ec);
    if (todo.empty() && haveReferences) return batch;

    // Before any fork: the references (threads, joined) and the shared images.
    std::vector<CheckScene> scenes = makeCheckScenes();
    writeReferenceImages(settings.out, scenes);
    if (todo.empty()) return batch;

    useRunShaderCache(settings.out);
    PoolLimits limits;
    limits.jobs = settings.jobs;
    // A worker that outlives every one of its checks timing out, plus staging, is stuck.
    // (+ two timeouts: the shared children of checkExercises() that may die before the fallback)
    limits.deadlineSeconds = double(settings.rubric.exercises.size() + 2) * (settings.timeoutSeconds + 15) + 120;
    // A check process orphaned by a killed worker still ends: each worker
    // (and each check it starts) gets at most this much CPU time, well above
    // what a check's wall-clock timeout allows llvmpipe's threads, so the
    // timeout always acts first.
    limits.cpuSeconds = double(std::uint64_t(settings.timeoutSeconds * (cpuCount() + 1) + 60));
    limits.childName = "a grading worker";
    std::size_t done = 0;
    progress.flush();
    auto work = [&](std::size_t k) { return workerMain(*todo[k], settings, scenes); };
    auto finished = [&](std::size_t k, const IsolatedResult& result) {
        const SubmissionEntry& entry = *todo[k];
        ++done;
        // Stopped on purpose: graded again next time.
        if (result.outcome == IsolatedResult::Outcome::Interrupted) return;
        bool clean = result.outcome == IsolatedResult::Outcome::Finished;
        std::optional<StudentGrade> grade = clean ? loadStudentGrade(settings.out, entry.id) : std::nullopt;
        if (!grade) {
            std::string why = result.outcome == IsolatedResult::Outcome::TimedOut
                                  ? "it took longer than the run allows for one student"
                                  : "worker " + (clean ? std::string("exited with status 0") : result.reason);
            grade = failedRecord(entry, settings.rubric, why);
            try {
                saveStudentGrade(settings.out, *grade);
                writeStudentOutputs(settings.out, settings.rubric, *grade);
            } catch (const std::exception& e) {
                // This student's folder cannot be written: said, and the class goes on.
                progress << "raylab: " << printable(std::string_view(e.what()), std::size_t(400)) << " (the class goes on without this student's files)\n";
            }
            ++batch.failed;
        }
        ++batch.graded;
        StudentScore score = scoreStudent(settings.rubric, *grade);
        char line[512];
        std::snprintf(line, sizeof line, "[%*zu/%zu] %-24s %7s / %s  (%.1f s)%s\n", int(std::to_string(todo.size()).size()),
                      done, todo.size(), printable(grade->id, 60).c_str(), formatPoints(score.total).c_str(),
                      formatPoints(settings.rubric.maxHundredths()).c_str(), grade->seconds,
                      grade->complete ? "" : "  GRADER FAILED, see its page");
        progress << line << std::flush;
    };
    batch.interrupted = runInPool(todo.size(), work, finished, limits);
    return batch;
}

int runGrade(const GradeRunOptions& options, std::ostream& log) {
    auto start = Clock::now();
    const GradeSettings& settings = options.settings;
    SubmissionList list = listSubmissions(options.submissions);
    std::vector<SubmissionEntry> slice;
    for (const SubmissionEntry& e : list.students)
        if (options.shardCount <= 1 || shardOf(e.id, options.shardCount) == options.shardIndex) slice.push_back(e);
    // Grading starts by clearing OUT/<id>/: never where the submissions are.
    if (pathsOverlap(settings.out, options.submissions))
        throw Error(settings.out.string() + ": the output folder must lie outside " + options.submissions.string() +
                    " (and hold no submissions)");
    for (const std::string& ignored : list.ignored) log << "ignored in " << printable(options.submissions.string(), 300) << ": " << printable(ignored, 300) << "\n";
    std::error_code ec;
    fs::create_directories(settings.out, ec);
    if (ec) throw Error(settings.out.string() + ": cannot create the output folder (" + ec.message() + ")");
    FolderLock lock(settings.out);
    log << "grading " << slice.size() << " of " << list.students.size() << " students";
    if (options.shardCount > 1) log << " (shard " << options.shardIndex << "/" << options.shardCount << ")";
    log << " into " << settings.out.string() << "\n";

    GradeBatch batch = gradeStudents(slice, settings, log);
    if (batch.interrupted) {
        log << "interrupted: the students finished so far are kept in " << settings.out.string()
            << "; run the same command again to grade the rest\n";
        return 130;
    }
    std::vector<StudentGrade> grades;
    for (const SubmissionEntry& e : slice) {
        std::optional<StudentGrade> g = loadStudentGrade(settings.out, e.id);
        grades.push_back(g ? *g : failedRecord(e, settings.rubric, "its record in OUT cannot be read"));
    }
    RunInfo info;
    info.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    info.graded = batch.graded;
    info.skipped = batch.skipped;
    info.jobs = settings.jobs;
    info.timeoutSeconds = settings.timeoutSeconds;
    info.shardIndex = options.shardIndex;
    info.shardCount = options.shardCount;
    info.submissionsTotal = list.students.size();
    info.ignored = list.ignored;
    if (!options.roster.empty() && options.shardCount <= 1)
        rosterCoverage(options.roster, grades, info.rosterWithoutSubmission, info.unmatchedSubmissions);
    nlohmann::json summary = gradeSummary(settings.rubric, grades, info);
    if (!options.roster.empty()) summary["roster_test_student"] = testStudentNote(options.roster);
    summary["similar_submissions"] = classSimilarity(settings.out, settings.rubric, grades);
    for (const std::string& failed : writeClassOutputs(settings.out, settings.rubric, grades, summary))
        log << "raylab: " << printable(failed, 400) << " (the class goes on without this student's files)\n";
    char line[256];
    std::snprintf(line, sizeof line, "graded %d, skipped %d (already graded), %d failed to grade, in %.1f s wall (%d jobs): ",
                  batch.graded, batch.skipped, batch.failed,
                  std::chrono::duration<double>(Clock::now() - start).count(), settings.jobs);
    log << line << (settings.out / "grades.csv").string() << ", " << (settings.out / "index.html").string() << "\n";
    return 0;
}

int runGradescope(const fs::path& root, GradeSettings settings, std::ostream& log) {
    const fs::path results = root / "results" / "results.json";
    auto fallback = [&](const std::string& why) {
        nlohmann::json j = {{"score", 0},
                            {"output", "raylab could not grade this submission: " + why},
                            {"output_format", "text"},
                            {"tests", nlohmann::json::array()}};
        writeOutputFile(results, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        log << "raylab grade --gradescope: " << why << "\n";
    };
    SubmissionEntry entry;
    entry.id = "submission";
    entry.path = root / "submission";
    entry.kind = SubmissionEntry::Kind::Folder;
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(entry.path, ec)) && !fs::is_symlink(fs::symlink_status(entry.path, ec))) {
        fallback(entry.path.string() + " is not a folder");
        return 0;
    }
    if (fs::is_symlink(fs::symlink_status(entry.path, ec))) entry.kind = SubmissionEntry::Kind::Link;
    settings.out = root / "results" / "raylab";
    settings.force = true;
    settings.jobs = 1;
    try {
        fs::create_directories(settings.out, ec);
        FolderLock lock(settings.out);
        GradeBatch batch = gradeStudents({entry}, settings, log);
        if (batch.interrupted) {
            fallback("the grader was interrupted");
            return 130;
        }
        std::optional<StudentGrade> grade = loadStudentGrade(settings.out, entry.id);
        if (!grade) {
            fallback("the grader failed");
            return 0;
        }
        writeOutputFile(results, readWholeFile(studentDir(settings.out, entry.id) / "results.json"));
        log << "wrote " << results.string() << "\n";
    } catch (const Error& e) {
        fallback(e.what());
    }
    return 0;
}

}  // namespace rl
