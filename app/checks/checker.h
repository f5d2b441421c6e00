// The exercise checker behind `raylab check` and `raylab grade`. For one
// exercise of one implementation folder:
//   1. NOT STARTED when the file is the shipped stub (or missing);
//   2. probes: the exercise's functions alone on a grid of inputs against
//      the CPU reference (checks/probe_cases.h);
//   3. images: the check scenes rendered with this exercise from the folder
//      and the solutions for all others, against the CPU reference.
// A student edition (scripts/student-edition.sh) has no solutions/: there the
// files beside the one under check are the student's own (missing ones the
// shipped stubs), the probes take only the earlier exercises that pass, and
// `raylab check` runs the image step only once every exercise passes its
// probes (commands/check_command.cpp; docs/decisions.md, "A student edition").
// Each exercise runs in its own child process (core/isolated.h) so that a
// shader that hangs or crashes costs that exercise only.
#pragma once

#include "course/exercise_registry.h"
#include "checks/probe_cases.h"
#include "core/image.h"
#include "core/scene.h"
#include "shader/shader_library.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rl {

enum class CheckStatus { Pass, Fail, NotStarted, CompileError, TimedOut, Crashed };
std::string statusName(CheckStatus status);  // "PASS", "FAIL", "NOT STARTED", "COMPILE ERROR", "TIMEOUT", "CRASH"

struct ProbeSummary {
    std::string name;  // "D_GGX"
    int passed = 0;
    int total = 0;
};

struct ImageSummary {
    std::string scene;
    bool passed = false;
    double offFraction = 0, meanLsb = 0;
    long nonFinite = 0;
    std::string expectedPng, gotPng, diffPng;  // written on failure (always with CheckOptions::writeAllImages)
};

struct ExerciseReport {
    int number = 0;
    std::string id;
    CheckStatus status = CheckStatus::Fail;
    std::string message;   // one line: what failed first, or why
    std::string hint;      // one line: what to look at
    std::string details;   // the failure table, compile log, image paths
    std::vector<ProbeSummary> probes;
    std::vector<ImageSummary> images;
    // A student edition: the exercise whose probes do not pass yet ("05-ggx"),
    // for which the image step waited; empty when it ran (or was not due).
    std::string imagesWaitingFor;
    double seconds = 0;

    double probeFraction() const;  // passed / total over all probes (0 when none ran)
    double imageFraction() const;  // check scenes within budget / all
};

nlohmann::json toJson(const ExerciseReport& report);
ExerciseReport reportFromJson(const nlohmann::json& j);

struct CheckOptions {
    std::filesystem::path implDir;          // the student's folder (exercises/ by default)
    std::filesystem::path outputDir = "check-output";  // expected/got/diff PNGs of failing images
    bool writeAllImages = false;            // also write them for passing images (grading reports)
    // The expected PNG of each image: false where the caller has the check
    // scenes' references already (grading: OUT/_reference/), so only its
    // path is reported.
    bool writeExpectedImages = true;
    double timeoutSeconds = 60;             // per exercise
    bool isolate = true;                    // run each exercise in a child process
    std::string backend = "auto";
    // When set, this file is checked as the exercise's implementation instead
    // of implDir/<id>.glsl (mutant tests; grading of nested folders).
    std::map<int, std::filesystem::path> fileOverride;
    // The probes alone, no image step (a student edition's first pass):
    // PASS when every probe passes. The other exercises are then the shipped
    // stubs, but for those in ownFiles: the student's (checkCompanions()).
    bool probesOnly = false;
    std::set<int> ownFiles;
};

// The check scenes and their CPU references, computed once and shared.
struct CheckScene {
    std::string name;
    Scene scene;
    Rendering reference;
};
std::vector<CheckScene> makeCheckScenes();
// Where a student edition keeps a check scene's reference rendering, recorded
// by the instructor's build (`raylab course --record DIR`): recorded/check-scenes/NAME.pfm
// (linear radiance) and .png (display), read when the reference is not in
// this copy (ref::referenceInThisCopy()).
std::filesystem::path checkReferenceFile(const std::string& scene, const char* extension);
Rendering recordedCheckReference(const std::string& scene);

// Checks one exercise (in a child process when options.isolate).
ExerciseReport checkExercise(const ExerciseInfo& exercise, const CheckOptions& options,
                             const std::vector<CheckScene>& scenes);

// The verdicts of checkExercise() for each of `exercises` (in that order).
// With options.isolate their checks share one child process (one driver
// start for a student's ten exercises instead of ten; issue #25), in two
// rounds: every exercise's probes, then the check scenes drawn once by one
// ray tracer of every file whose probes pass; an exercise takes each of
// those pictures that is within the budget, and draws a scene with its own
// ray tracer (its file, the companions for the rest) only where it is not
// (docs/decisions.md, "The check scenes drawn once per student"). When that
// child dies while probing an exercise (its timeout, a crash, the memory
// limit), that exercise is checked in its own child and the rest in a new
// shared child that keeps the probes they passed; after a second death, or
// one while drawing, each exercise left is checked in its own child, as
// checkExercise() does.
std::vector<ExerciseReport> checkExercises(const std::vector<const ExerciseInfo*>& exercises,
                                           const CheckOptions& options, const std::vector<CheckScene>& scenes);

// The verdict on one probe, from the GPU's results (RGB of one texel per
// case): the counts, the first failure, the table and a hint that names a
// cause only when the student's numbers support it (a known mistake matched
// on every case, one constant factor on every case, or a group whose
// failures stand out); otherwise it says where it fails, with the counts.
struct ProbeOutcome {
    ProbeSummary summary;
    bool allStub = true;
    std::string firstFailure;  // one line
    std::string table;
    std::string hint;
};
ProbeOutcome evaluateProbe(const ProbeSpec& spec, const std::vector<std::array<float, 4>>& raw);

// The last step of `raylab check`: every exercise file of the folder (with
// options.fileOverride) compiled together into the ray tracer, as `raylab
// render` compiles them, in a child process like the exercises. Two files
// that each pass alone can still clash (both define a helper `pow5`).
// Status Pass or CompileError (TimedOut, Crashed); id "all files". nullopt,
// without compiling, when a file of the ten is missing (each is NOT STARTED).
std::optional<ExerciseReport> checkTogether(const CheckOptions& options);

// The files a check compiles beside `file` (the exercise under check): the
// solutions where the repository has them. In a student edition the
// student's own files (options.implDir with options.fileOverride; a missing
// one the shipped stub); with options.probesOnly only those of the exercises
// in options.ownFiles (the earlier ones that pass their probes), the shipped
// stubs for every other, so that an exercise that does not pass yet (a
// compile error, a runaway loop, wrong numbers) cannot fail this one.
Implementation checkCompanions(const ExerciseInfo& exercise, const std::filesystem::path& file,
                               const CheckOptions& options);

// A student edition's `raylab check` (no solutions/), in two passes. First
// the probes of all ten exercises in the teaching order, each beside the
// student's files of the earlier ones that pass theirs (options.probesOnly,
// options.ownFiles; checkCompanions()).
std::map<int, ExerciseReport> checkProbesOfAll(const CheckOptions& options, const std::vector<CheckScene>& scenes);
// Then each exercise's verdict: when every exercise passes its probes, the
// full check with the student's own files (its image step included);
// otherwise the first pass's report, a PASS saying which exercise its image
// step waits for (imagesWaitingFor), a FAIL whose hint names the first
// exercise it calls (its files, its unit's "needs" and "framework_calls")
// that does not pass yet, and no other. A check scene runs every exercise: with any of them
// wrong, its picture says nothing about the one under check.
ExerciseReport checkWithOwnFiles(const ExerciseInfo& exercise, const CheckOptions& options,
                                 const std::vector<CheckScene>& scenes, const std::map<int, ExerciseReport>& firstPass);

// The exercises (numbers) whose functions the files of `impl` for `exercise`
// call, directly or through each other, or that their units declare
// ("needs"; "framework_calls": what the framework calls on their behalf,
// mapped to false); `exercise` itself not included.
std::map<int, bool> exercisesCalled(const ExerciseInfo& exercise, const Implementation& impl);

// The one-line verdict printed by `raylab check` for a report, plus its hint
// and details on the following lines (indented).
std::string formatReport(const ExerciseReport& report, bool verbose);

}  // namespace rl
