// raylab check [--impl DIR] [--exercise N]... [--json FILE] [--output DIR] [--timeout S] [--verbose]
// One line per exercise: PASS, FAIL, NOT STARTED, COMPILE ERROR, TIMEOUT or
// CRASH, with the first failure and a hint; then, when the ten files of the
// folder do not compile together as `render` compiles them, one "all files"
// line with the error. Exit 0 only when every selected exercise passes and
// the files compile together.
//
// In a student edition (no solutions/): first the probes of all ten
// exercises, then the image step only once all ten pass them; until then
// PASS rests on the probes and says "images waiting for exercise NN"
// (checks/checker.h, checkWithOwnFiles(); docs/decisions.md, "A student edition").
#include "commands/commands.h"

#include "checks/checker.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/paths.h"
#include "gl/context.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <optional>
#include <filesystem>
#include <iostream>
#include <map>

namespace rl {
namespace {

struct CheckCommandOptions {
    std::string impl;
    std::vector<std::string> exercises;
    std::string json;
    std::string output = "check-output";
    std::string file;
    double timeout = 60;
    std::string backend = "auto";
    bool verbose = false;
};

int runCheck(const CheckCommandOptions& o) {
    auto start = std::chrono::steady_clock::now();
    std::error_code ec;
    if (!o.json.empty()) requireOutputPath(o.json, "the JSON report");
    parseBackend(o.backend);  // refused now, not in every exercise's worker
    if (std::filesystem::exists(o.output, ec) && !std::filesystem::is_directory(o.output, ec))
        throw Error("--output: " + o.output + " exists and is not a folder");
    CheckOptions options;
    options.implDir = o.impl.empty() ? exercisesDir() : std::filesystem::path(o.impl);
    options.outputDir = o.output;
    options.timeoutSeconds = o.timeout;
    options.backend = o.backend;
    if (o.file.empty() && !std::filesystem::is_directory(options.implDir, ec))
        throw Error("--impl: " + options.implDir.string() + " is not a directory");

    std::vector<ExerciseInfo> selected;
    for (const std::string& key : o.exercises) selected.push_back(findExercise(key));
    if (selected.empty()) selected = allExercises();
    if (!o.file.empty()) {
        if (selected.size() != 1) throw Error("--file needs exactly one --exercise");
        if (!std::filesystem::is_regular_file(o.file, ec)) throw Error("--file: " + o.file + ": file not found");
        options.fileOverride[selected[0].number] = o.file;
    }

    std::vector<CheckScene> scenes = makeCheckScenes();
    nlohmann::json all = nlohmann::json::array();
    // An optional exercise (course/manifest.txt) is checked like the others
    // but counts apart: "10 of 10 exercises pass; optional 11-environment: NOT STARTED".
    // Its verdict sets the exit status only where it was asked for by name
    // (--exercise 11): then it is what the command checks.
    const bool named = !o.exercises.empty();
    int passed = 0, required = 0;
    bool optionalsPass = true;
    std::string optionals;
    auto print = [&](const ExerciseReport& report) {
        std::cout << formatReport(report, o.verbose) << std::flush;
        const bool optional = findExercise(report.id).optional;
        if (optional) optionals += "; optional " + report.id + ": " + statusName(report.status);
        if (optional && report.status != CheckStatus::Pass) optionalsPass = false;
        if (!optional) required += 1;
        if (report.status == CheckStatus::Pass && !optional) ++passed;
        all.push_back(toJson(report));
    };
    if (hasSolutions()) {
        for (const ExerciseInfo& exercise : selected) print(checkExercise(exercise, options, scenes));
    } else {
        const std::map<int, ExerciseReport> firstPass = checkProbesOfAll(options, scenes);
        for (const ExerciseInfo& exercise : selected) print(checkWithOwnFiles(exercise, options, scenes, firstPass));
    }
    // Then the ten files together, as render compiles them: when some
    // exercise got as far as PASS or FAIL and none failed to build (its error
    // would only repeat); not for --file, which checks one file, not a folder.
    auto statusIs = [&](CheckStatus s) {
        return std::any_of(all.begin(), all.end(),
                           [&](const nlohmann::json& j) { return j.value("status", "") == statusName(s); });
    };
    bool started = statusIs(CheckStatus::Pass) || statusIs(CheckStatus::Fail);
    bool builds = !statusIs(CheckStatus::CompileError) && !statusIs(CheckStatus::TimedOut) &&
                  !statusIs(CheckStatus::Crashed);
    std::optional<ExerciseReport> together;
    if (o.file.empty() && started && builds) together = checkTogether(options);
    bool togetherOk = !together || together->status == CheckStatus::Pass;
    if (!togetherOk) std::cout << formatReport(*together, o.verbose) << std::flush;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Only optional exercises selected (--exercise 11): their verdicts alone.
    if (required == 0 && !optionals.empty()) optionals.erase(0, 2);
    std::cout << (required > 0 || optionals.empty() ? std::to_string(passed) + " of " + std::to_string(required) + " exercises pass" : "")
              << optionals
              << (togetherOk ? "" : "; the files do not compile together") << " (" << int(seconds + 0.5) << " s)\n";
    if (!o.json.empty()) {
        nlohmann::json report{{"impl", options.implDir.string()}, {"exercises", all}, {"seconds", seconds}};
        if (together) report["together"] = toJson(*together);
        writeFileAtomic(o.json, report.dump(2) + "\n", WriteOptions{"the JSON report"});
    }
    return passed == required && togetherOk && (!named || optionalsPass) ? 0 : 1;
}

}  // namespace

void addCheckCommand(CLI::App& app) {
    auto o = std::make_shared<CheckCommandOptions>();
    CLI::App* cmd = app.add_subcommand("check", "Check exercise implementations against the CPU reference");
    cmd->add_option("--impl", o->impl, "Folder with the exercise files (default: exercises/)")->check(notEmpty());
    cmd->add_option("-e,--exercise", o->exercises, "Exercise to check, by number or name (repeatable; default: all)");
    cmd->add_option("--file", o->file, "Check this file as the implementation of the one --exercise")
        ->check(notEmpty());
    cmd->add_option("--json", o->json, "Also write the results as JSON")->check(notEmpty());
    cmd->add_option("--output", o->output, "Where expected/got/diff PNGs of failing images go")
        ->capture_default_str()
        ->check(notEmpty());
    cmd->add_option("--timeout", o->timeout, "Seconds allowed per exercise")
        ->capture_default_str()
        ->check(secondsIn(0, 86400));
    cmd->add_option("--backend", o->backend, "OpenGL backend: auto, egl, osmesa or glfw (a hidden window)")->capture_default_str();
    cmd->add_flag("-v,--verbose", o->verbose, "Print every detail");
    cmd->callback([o] {
        int status = runCheck(*o);
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

}  // namespace rl
