// raylab grade SUBMISSIONS -o OUT [--jobs N] [--timeout S] [--rubric FILE]
//              [--id-column NAME] [--shard I/N] [--force]
// raylab grade merge SHARD_OUT... -o OUT
// raylab grade export OUT --format canvas|moodle|csv [--roster FILE] ...
// raylab grade --gradescope [--gradescope-root DIR]
// Batch grading for instructors (docs/grading.md): every student of
// SUBMISSIONS graded in isolated processes, grades.csv, Gradescope
// results.json per student, an HTML report and summary.json in OUT.
#include "commands/commands.h"

#include "core/error.h"
#include "gl/context.h"
#include "core/message.h"
#include "grading/grade_run.h"
#include "grading/lms_export.h"
#include "grading/merge.h"
#include "grading/rubric.h"

#include <cstdlib>
#include <iostream>

namespace rl {
namespace {

struct GradeCommandOptions {
    std::string submissions;
    std::string out;
    int jobs = 1;
    double timeout = 30;
    std::string rubric;
    std::string idColumn;
    std::string shard;
    bool force = false;
    std::string backend = "auto";
    bool gradescope = false;
    std::string gradescopeRoot;
    std::vector<std::string> mergeInputs;
    std::string mergeOut;
    std::vector<std::string> exports;  // --export (grade) / --format (grade export)
    ExportOptions exportOptions;
    std::string exportOut;             // grade export: OUT
};

void parseShard(const std::string& text, int& index, int& count) {
    auto slash = text.find('/');
    try {
        if (slash == std::string::npos) throw std::invalid_argument(text);
        std::size_t used = 0;
        index = std::stoi(text.substr(0, slash), &used);
        if (used != slash) throw std::invalid_argument(text);
        count = std::stoi(text.substr(slash + 1), &used);
        if (used != text.size() - slash - 1) throw std::invalid_argument(text);
    } catch (const std::logic_error&) {
        throw Error("--shard: expected I/N, e.g. 2/8, got " + quotedValue(text));
    }
    if (count < 1 || index < 1 || index > count)
        throw Error("--shard: " + text + " is not a slice: I must be between 1 and N");
}

GradeSettings settingsFrom(const GradeCommandOptions& o) {
    GradeSettings s;
    if (o.jobs < 1) throw Error("--jobs: must be at least 1");
    if (!(o.timeout > 0)) throw Error("--timeout: must be more than 0 seconds");
    parseBackend(o.backend);  // refused now, not in every student's worker
    // Named by its option, the path quoted short: a path too long for one line of message named
    // nothing (found by the fuzzer, issue 22).
    std::error_code ec;
    if (!o.rubric.empty() && !std::filesystem::is_regular_file(o.rubric, ec))
        throw Error("--rubric: " + quotedValue(o.rubric) + ": rubric file not found");
    s.rubric = loadRubric(o.rubric.empty() ? defaultRubricPath() : std::filesystem::path(o.rubric));
    if (!o.idColumn.empty()) s.rubric.idColumn = o.idColumn;
    s.out = o.out;
    s.jobs = o.jobs;
    s.timeoutSeconds = o.timeout;
    s.force = o.force;
    s.backend = o.backend;
    return s;
}

// Writes each export asked for; 0, or 3 when a submission was left out of one.
int runExports(const GradeCommandOptions& o, const std::filesystem::path& out) {
    int status = 0;
    for (const std::string& format : o.exports) {
        ExportOptions e = o.exportOptions;
        e.format = format;
        ExportReport report = exportGrades(out, e);
        printExportReport(report, format, std::cout);
        if (!report.unmatched.empty()) status = 3;
    }
    return status;
}

// Every export asked for, checked before the first student is graded: a
// wrong roster or option found after hours of grading costs the hours.
void checkExports(const GradeCommandOptions& o) {
    for (const std::string& format : o.exports) {
        ExportOptions e = o.exportOptions;
        e.format = format;
        checkExportOptions(e);
    }
}

int runGradeCommand(const GradeCommandOptions& o, bool merge, bool exportOnly) {
    checkExports(o);
    if (exportOnly) {
        if (o.exports.empty()) throw Error("grade export: --format canvas|moodle|csv is required");
        if (o.exports.size() > 1 && !o.exportOptions.output.empty())
            throw Error("grade export: -o FILE names one file; give one --format with it");
        return runExports(o, o.exportOut);
    }
    if (!o.exportOptions.roster.empty() && o.exports.empty())
        throw Error("--roster: give --export canvas|moodle with it");
    if (merge) {
        if (o.mergeOut.empty()) throw Error("grade merge: -o OUT is required");
        std::vector<std::filesystem::path> inputs(o.mergeInputs.begin(), o.mergeInputs.end());
        mergeGradeOutputs(inputs, o.mergeOut, std::cout);
        return runExports(o, o.mergeOut);
    }
    if (o.gradescope) {
        std::string root = o.gradescopeRoot;
        if (root.empty()) {
            const char* env = std::getenv("RAYLAB_GRADESCOPE_ROOT");
            root = env && *env ? env : "/autograder";
        }
        GradeCommandOptions withOut = o;
        withOut.out = root + "/results/raylab";
        return runGradescope(root, settingsFrom(withOut), std::cout);
    }
    if (o.submissions.empty()) throw Error("grade: name the SUBMISSIONS folder (or use --gradescope)");
    if (o.out.empty()) throw Error("grade: -o OUT is required");
    GradeRunOptions run;
    run.submissions = o.submissions;
    run.settings = settingsFrom(o);
    if (!o.shard.empty()) parseShard(o.shard, run.shardIndex, run.shardCount);
    run.roster = o.exportOptions.roster;
    int status = runGrade(run, std::cout);
    if (status != 0) return status;
    return runExports(o, run.settings.out);
}

}  // namespace

void addGradeCommand(CLI::App& app) {
    auto o = std::make_shared<GradeCommandOptions>();
    CLI::App* cmd = app.add_subcommand("grade", "Grade a class of submissions: grades.csv, Gradescope JSON, HTML report");
    cmd->add_option("submissions", o->submissions, "Folder with one folder or .zip per student")->check(notEmpty());
    cmd->add_option("-o,--output", o->out, "Output folder (a second run skips students already graded there)")
        ->check(notEmpty());
    cmd->add_option("-j,--jobs", o->jobs, "Students graded at the same time")
        ->capture_default_str()
        ->check(wholeNumberIn(1, 256));
    cmd->add_option("--timeout", o->timeout, "Seconds allowed per exercise")
        ->capture_default_str()
        ->check(secondsIn(0, 86400));
    cmd->add_option("--rubric", o->rubric, "Rubric JSON (default: grading/default-rubric.json)")->check(notEmpty());
    cmd->add_option("--id-column", o->idColumn, "Header of the id column in grades.csv (e.g. Username)");
    cmd->add_option("--shard", o->shard, "Grade only slice I of N (I/N); join the slices with `grade merge`")
        ->check(notEmpty());
    cmd->add_flag("--force", o->force, "Grade again students already graded in OUT");
    cmd->add_option("--backend", o->backend, "OpenGL backend: auto, egl, osmesa or glfw (a hidden window)")->capture_default_str();
    cmd->add_flag("--gradescope", o->gradescope,
                  "Run as Gradescope's autograder: ROOT/submission in, ROOT/results/results.json out");
    cmd->add_option("--gradescope-root", o->gradescopeRoot,
                    "ROOT for --gradescope (default: $RAYLAB_GRADESCOPE_ROOT, else /autograder)");
    auto exportOptions = [o](CLI::App* c, const char* formatFlag) {
        c->add_option(formatFlag, o->exports, "Gradebook export: canvas, moodle or csv (repeat for more)")
            ->check(CLI::IsMember({"canvas", "moodle", "csv"}));
        c->add_option("--roster", o->exportOptions.roster,
                      "The LMS's class export (Canvas gradebook CSV, Moodle grading worksheet or grades CSV)");
        c->add_option("--assignment", o->exportOptions.assignment,
                      "Assignment (Canvas) or grade item (Moodle) column name (default: the rubric's total_column)");
        c->add_option("--moodle-id", o->exportOptions.moodleId, "Moodle identifier column: username, idnumber or email")
            ->capture_default_str();
        c->add_flag("--exercise-columns", o->exportOptions.exerciseColumns,
                    "Per-exercise columns too (read-only in Canvas)");
    };
    exportOptions(cmd, "--export");
    CLI::App* merge = cmd->add_subcommand("merge", "Join the outputs of `grade --shard I/N` runs into one");
    merge->add_option("shards", o->mergeInputs, "Output folders of the shards")->required();
    merge->add_option("-o,--output", o->mergeOut, "Merged output folder")->required();
    exportOptions(merge, "--export");
    CLI::App* exporter = cmd->add_subcommand("export", "Write a gradebook file for Canvas or Moodle from a finished run");
    exporter->add_option("out", o->exportOut, "Output folder of `raylab grade` (or of `grade merge`)")->required();
    exportOptions(exporter, "--format");
    exporter->add_option("-o,--output", o->exportOptions.output, "File to write (default: OUT/grades-FORMAT.csv)");
    cmd->callback([o, merge, exporter] {
        int status = runGradeCommand(*o, merge->parsed(), exporter->parsed());
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

}  // namespace rl
