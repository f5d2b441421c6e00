#include "checks/checker.h"

#include "course/fallback_files.h"
#include "checks/probe_cases.h"
#include "checks/probe_runner.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/isolated.h"
#include "core/process_pool.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "core/scene_transform.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "shader/glsl_scan.h"
#include "shader/loop_guard.h"
#include "shader/portability.h"
#include "shader/shader_library.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace rl {

using nlohmann::json;

std::string statusName(CheckStatus s) {
    switch (s) {
        case CheckStatus::Pass: return "PASS";
        case CheckStatus::Fail: return "FAIL";
        case CheckStatus::NotStarted: return "NOT STARTED";
        case CheckStatus::CompileError: return "COMPILE ERROR";
        case CheckStatus::TimedOut: return "TIMEOUT";
        case CheckStatus::Crashed: return "CRASH";
    }
    return "FAIL";
}

double ExerciseReport::probeFraction() const {
    int passed = 0, total = 0;
    for (const auto& p : probes) {
        passed += p.passed;
        total += p.total;
    }
    return total ? double(passed) / total : 0.0;
}

double ExerciseReport::imageFraction() const {
    if (images.empty()) return 0.0;
    return double(std::count_if(images.begin(), images.end(), [](const ImageSummary& i) { return i.passed; })) /
           double(images.size());
}

json toJson(const ExerciseReport& r) {
    json j = {{"exercise", r.id}, {"number", r.number}, {"status", statusName(r.status)}, {"message", r.message},
              {"hint", r.hint}, {"details", r.details}, {"seconds", r.seconds},
              {"probe_fraction", r.probeFraction()}, {"image_fraction", r.imageFraction()}};
    j["probes"] = json::array();
    for (const auto& p : r.probes) j["probes"].push_back({{"name", p.name}, {"passed", p.passed}, {"total", p.total}});
    j["images"] = json::array();
    for (const auto& i : r.images)
        j["images"].push_back({{"scene", i.scene}, {"passed", i.passed}, {"off_fraction", i.offFraction},
                               {"mean_lsb", i.meanLsb}, {"non_finite", i.nonFinite}, {"expected", i.expectedPng},
                               {"got", i.gotPng}, {"diff", i.diffPng}});
    if (!r.imagesWaitingFor.empty()) j["images_waiting_for"] = r.imagesWaitingFor;
    return j;
}

ExerciseReport reportFromJson(const json& j) {
    ExerciseReport r;
    r.id = j.value("exercise", "");
    r.number = j.value("number", 0);
    std::string status = j.value("status", "FAIL");
    for (CheckStatus s : {CheckStatus::Pass, CheckStatus::Fail, CheckStatus::NotStarted, CheckStatus::CompileError,
                          CheckStatus::TimedOut, CheckStatus::Crashed})
        if (statusName(s) == status) r.status = s;
    r.message = j.value("message", "");
    r.hint = j.value("hint", "");
    r.details = j.value("details", "");
    r.seconds = j.value("seconds", 0.0);
    r.imagesWaitingFor = j.value("images_waiting_for", "");
    for (const auto& p : j.value("probes", json::array()))
        r.probes.push_back({p.value("name", ""), p.value("passed", 0), p.value("total", 0)});
    for (const auto& i : j.value("images", json::array())) {
        ImageSummary s;
        s.scene = i.value("scene", "");
        s.passed = i.value("passed", false);
        s.offFraction = i.value("off_fraction", 0.0);
        s.meanLsb = i.value("mean_lsb", 0.0);
        s.nonFinite = i.value("non_finite", 0L);
        s.expectedPng = i.value("expected", "");
        s.gotPng = i.value("got", "");
        s.diffPng = i.value("diff", "");
        r.images.push_back(s);
    }
    return r;
}

// ---- check scenes ------------------------------------------------------------------------

std::filesystem::path checkReferenceFile(const std::string& scene, const char* extension) {
    return sourceRoot() / "recorded" / "check-scenes" / (scene + extension);
}

Rendering recordedCheckReference(const std::string& scene) {
    Rendering r;
    r.radiance = readPfm(checkReferenceFile(scene, ".pfm").string());
    r.display = readPng(checkReferenceFile(scene, ".png").string());
    return r;
}

std::vector<CheckScene> makeCheckScenes() {
    auto sized = [](Scene s, int w, int h) {
        s.render.width = w;
        s.render.height = h;
        return s;
    };
    auto load = [](const std::string& name) { return loadSceneFile((scenesDir() / name).string()).scene; };
    // Small sizes: the whole check stays within seconds on llvmpipe, and each
    // scene still has thousands of pixels of every feature it tests.
    Scene lecture = sized(defaultScene(), 96, 72);
    Scene wide = sized(defaultScene(), 128, 48);  // aspect 8:3, 4 samples, sRGB, exponential: camera and display
    wide.render.spp = 4;
    wide.render.srgb = true;
    wide.render.tonemap = ToneMap::Exponential;
    wide.render.exposure = 1.5;
    std::vector<CheckScene> list = {
        {"dielectric-row", sized(load("dielectric-row-reflections.json"), 96, 72), {}},
        {"metal-row", sized(load("metal-row-reflections.json"), 96, 72), {}},
        {"lecture", lecture, {}},
        {"lecture-scaled-1e-3", scaledScene(lecture, 1e-3), {}},
        {"wide-srgb-4spp", wide, {}},
    };
    for (CheckScene& c : list)
        c.reference = ref::referenceInThisCopy() ? ref::renderCpu(c.scene) : recordedCheckReference(c.name);
    return list;
}

namespace {

// ---- probes --------------------------------------------------------------------------------

std::string fmt(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return b;
}

std::string valueText(const ProbeValue& v, int outputs) {
    if (outputs == 1) return fmt(v[0]);
    std::string s = "(";
    for (int i = 0; i < outputs; ++i) s += (i ? ", " : "") + fmt(v[i]);
    return s + ")";
}

bool within(const ProbeValue& got, const ProbeValue& want, int outputs, std::pair<double, double> tol) {
    for (int i = 0; i < outputs; ++i) {
        if (!std::isfinite(got[i])) return false;
        if (std::fabs(got[i] - want[i]) > tol.first + tol.second * std::fabs(want[i])) return false;
    }
    return true;
}

// Every value is the right one times the same factor k (fitted as the
// median ratio, then checked on every case within the tolerance): a constant
// slipped. Empty when no single factor explains all the numbers.
std::optional<double> commonFactor(const ProbeSpec& spec, const std::vector<ProbeValue>& got,
                                   const std::vector<ProbeValue>& want) {
    std::vector<double> ratios;
    for (std::size_t k = 0; k < got.size(); ++k)
        for (int i = 0; i < spec.outputs; ++i)
            if (want[k][i] != 0 && std::isfinite(got[k][i]) && std::fabs(got[k][i] - want[k][i]) > 0)
                ratios.push_back(got[k][i] / want[k][i]);
    if (ratios.empty()) return std::nullopt;
    std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(ratios.size() / 2), ratios.end());
    double factor = ratios[ratios.size() / 2];
    if (!std::isfinite(factor) || factor <= 0) return std::nullopt;
    for (std::size_t k = 0; k < got.size(); ++k) {
        ProbeValue scaled = {factor * want[k][0], factor * want[k][1], factor * want[k][2]};
        if (!within(got[k], scaled, spec.outputs, spec.tolerance(spec.cases[k]))) return std::nullopt;
    }
    return factor;
}

// The constant slips a factor k points at (k = student / right).
std::string constantSlip(double factor) {
    constexpr double pi = 3.14159265358979323846;
    const std::pair<double, const char*> slips[] = {
        {pi / 3.14, "pi written as 3.14"},          {3.14 / pi, "pi written as 3.14"},
        {pi / 3.1416, "pi written as 3.1416"},      {3.1416 / pi, "pi written as 3.1416"},
        {pi / 3.14159, "pi written as 3.14159"},    {3.14159 / pi, "pi written as 3.14159"},
        {pi / (22.0 / 7.0), "pi written as 22/7"},  {(22.0 / 7.0) / pi, "pi written as 22/7"},
        {0.318 * pi, "1/pi written as 0.318"},      {0.3183 * pi, "1/pi written as 0.3183"},
    };
    // The factor is fitted from float32 results: good to ~1e-7, and the
    // nearest two slips above (3.1416 and 3.14159) are 3e-6 apart.
    for (const auto& [k, name] : slips)
        if (std::fabs(factor / k - 1) < 1e-6) return std::string(name) + ": use PI from shaders/common.glsl";
    return "";
}

std::string countText(int failed, int total) { return std::to_string(failed) + " of " + std::to_string(total); }

}  // namespace

ProbeOutcome evaluateProbe(const ProbeSpec& spec, const std::vector<std::array<float, 4>>& raw) {
    ProbeOutcome out;
    out.summary.name = spec.name;
    out.summary.total = int(spec.cases.size());
    std::vector<ProbeValue> got(spec.cases.size()), want(spec.cases.size());
    std::map<std::string, std::pair<int, int>> groups;  // group -> (failed, total)
    std::vector<std::size_t> failures;
    for (std::size_t k = 0; k < spec.cases.size(); ++k) {
        got[k] = {raw[k][0], raw[k][1], raw[k][2]};
        if (raw[k][0] != kNotStarted) out.allStub = false;
        want[k] = spec.expected(spec.cases[k]);
        bool ok = within(got[k], want[k], spec.outputs, spec.tolerance(spec.cases[k]));
        auto& g = groups[spec.cases[k].group];
        ++g.second;
        if (ok) {
            ++out.summary.passed;
        } else {
            ++g.first;
            failures.push_back(k);
        }
    }
    const int failed = int(failures.size()), total = out.summary.total;
    if (failed == 0 || out.allStub) return out;
    auto result = [&](std::size_t k) {
        return "expected " + valueText(want[k], spec.outputs) + ", got " + valueText(got[k], spec.outputs);
    };
    const std::size_t first = failures.front();
    out.firstFailure = spec.name + ": " + countText(failed, total) + " cases wrong; first: " +
                       spec.describe(spec.cases[first]) + ": " + result(first);
    const int shown = std::min(failed, 5);
    out.table = "  " + spec.signature + ": " + countText(failed, total) + " cases wrong (first " +
                std::to_string(shown) + "):\n";
    for (int i = 0; i < shown; ++i) {
        std::size_t k = failures[std::size_t(i)];
        out.table += "    " + spec.describe(spec.cases[k]) + "  [" + spec.cases[k].group + "]\n      " + result(k) + "\n";
    }
    // A hint names a cause only when the numbers support it.
    // 1. A known mistake: the student's numbers match the mistaken formula on
    //    EVERY case (also where it agrees with the right answer), and the
    //    formula differs from the right answer somewhere.
    for (const KnownMistake& m : spec.mistakes) {
        bool matchesAll = true, differs = false;
        for (std::size_t k = 0; k < spec.cases.size() && matchesAll; ++k) {
            ProbeValue wrong = m.compute(spec.cases[k]);
            auto tol = spec.tolerance(spec.cases[k]);
            differs = differs || !within(wrong, want[k], spec.outputs, tol);
            matchesAll = within(got[k], wrong, spec.outputs, tol);
        }
        if (matchesAll && differs) {
            out.hint = "looks like: " + m.symptom + ". " + m.hint;
            return out;
        }
    }
    // 2. Every value off by the same factor: a constant slipped.
    if (std::optional<double> factor = commonFactor(spec, got, want)) {
        char text[64];
        std::snprintf(text, sizeof text, "%.7g", *factor);
        std::string slip = constantSlip(*factor);
        out.hint = "every value is " + std::string(text) + " times the right one: " +
                   (slip.empty() ? std::string("a constant factor is off") : slip);
        return out;
    }
    // 3. A group hint, when that group's failures stand out: it holds at least
    //    half of the failures, and the other inputs fail at most a quarter as
    //    often as its own cases.
    const std::pair<std::string, std::string>* best = nullptr;
    double bestRate = 0;
    for (const auto& groupHint : spec.groupHints) {
        auto it = groups.find(groupHint.first);
        if (it == groups.end()) continue;
        auto [groupFailed, groupTotal] = it->second;
        double rate = double(groupFailed) / groupTotal;
        int restTotal = total - groupTotal;
        double restRate = restTotal ? double(failed - groupFailed) / restTotal : 0.0;
        bool standsOut = 2 * groupFailed >= failed && restRate <= rate / 4;
        if (standsOut && rate > bestRate) {
            best = &groupHint;
            bestRate = rate;
        }
    }
    if (best) {
        out.hint = "fails mostly on " + best->first + ": " + best->second;
        return out;
    }
    // 4. No cause the numbers support: say where it fails, with the counts.
    bool everyGroupFails = std::all_of(groups.begin(), groups.end(), [](const auto& g) { return g.second.first > 0; });
    if (everyGroupFails) {
        // Every group, but perhaps not every case: say which, so that "6 of
        // 45" does not read as "everywhere".
        out.hint = (failed == total ? "fails on all " + std::to_string(total) + " cases, of every kind"
                                    : "fails on " + countText(failed, total) + " cases, some of every kind") +
                   ": compare your formula with the handout, term by term";
        return out;
    }
    std::vector<std::pair<std::string, std::pair<int, int>>> failing;
    for (const auto& g : groups)
        if (g.second.first > 0) failing.push_back(g);
    std::sort(failing.begin(), failing.end(), [](const auto& a, const auto& b) {
        return a.second.first * b.second.second > b.second.first * a.second.second;  // highest failure rate first
    });
    std::string where;
    for (const auto& [group, counts] : failing)
        where += (where.empty() ? "" : ", ") + group + " (" + countText(counts.first, counts.second) + ")";
    out.hint = "fails on " + where + "; every other kind of input passes: compare your formula with the handout "
               "on these inputs";
    return out;
}

namespace {

// ---- one exercise, inside the child --------------------------------------------------------

// What the check's child process is doing, kept where its parent can read
// it after the end (core/isolated.h), so that a wall-clock timeout can say
// what ran out of time: the compiler, or the shader.
void setPhase(const std::string& phase) { setIsolatedPhase(phase); }

// TIMEOUT for a loop that went over the guard's bound (shader/loop_guard.h).
ExerciseReport& loopTimeout(ExerciseReport& report, const ShaderProgram& program, int loop, const std::string& where) {
    report.status = CheckStatus::TimedOut;
    report.message = loopTimeoutMessage(program.guardedLoops(), loop, where);
    report.hint = "every loop needs a bound that it reaches: check the loop's condition and what changes it";
    report.probes.clear();
    report.images.clear();
    return report;
}

// llvmpipe: LLVM's optimisation passes are most of a check's time (a check
// compiles two shaders and runs them on a few thousand pixels, once), so the
// check's child turns them off (GALLIVM_PERF=nopt, llvmpipe's own switch; a
// value the user set wins). They change how fast the code runs, not what it
// computes (llvmpipe's IR carries no fast-math flags): the solutions and the
// mutants gave byte-identical records and images with and without (docs/grading.md).
void fastShaderCompiles() { setenv("GALLIVM_PERF", "nopt", 0); }

std::string imagePath(const fs::path& dir, const std::string& scene, const std::string& kind) {
    return (dir / (scene + "-" + kind + ".png")).string();
}

// The exercise's file, and its report when no check needs to run (missing,
// the unchanged stub).
fs::path exerciseFile(const ExerciseInfo& exercise, const CheckOptions& options) {
    auto it = options.fileOverride.find(exercise.number);
    return it != options.fileOverride.end() ? it->second : options.implDir / exercise.file();
}

std::optional<ExerciseReport> withoutCheck(const ExerciseInfo& exercise, const fs::path& file) {
    ExerciseReport report;
    report.number = exercise.number;
    report.id = exercise.id;
    std::error_code ec;
    if (!fs::exists(file, ec)) {
        report.status = CheckStatus::NotStarted;
        report.message = file.string() + " is missing";
        report.hint = "copy the stub " + exercise.stubFile() + " to " + file.string() + " and start with " + exercise.handout();
        return report;
    }
    if (isUnchangedStub(file, exercise)) {
        report.status = CheckStatus::NotStarted;
        report.message = "the file is the unchanged stub";
        report.hint = "start with the handout: " + exercise.handout();
        return report;
    }
    return std::nullopt;
}


// One exercise's check in two stages, so that checkExercises() can run every
// exercise's probes before any picture (a file that is slow shows there,
// before it costs the others their images) and draw the check scenes once
// for the whole submission.

// What the probe stage leaves: the report so far (its probes, the first
// failure's message and hint, the failure table in `details`), and whether
// it is the verdict already (not started, a compile error, a loop that ran
// away, the probes alone asked for). Otherwise the image stage finishes it.
struct ProbeStage {
    ExerciseReport report;
    bool final = false;
};

// A check scene drawn once with the student's whole submission (every file
// whose probes pass; checkExercises()) and within the budget: the exercises
// in it take this picture instead of drawing their own.
struct SharedPicture {
    ImageDiff diff;
    std::string gotPng, diffPng;  // written once, for every exercise (CheckOptions::writeAllImages)
};

// The budget of a check scene, the course core's (issue 2): <= 0.5% of
// pixels off by more than 1/255, mean difference < 0.2/255, no NaN or Inf;
// each part apart, for the failure's message.
struct ImageBudget {
    bool pixelsOk, meanOk, finite;
    bool within() const { return pixelsOk && meanOk && finite; }
};
ImageBudget imageBudget(const ImageDiff& diff) {
    return {diff.offFraction <= 0.005, diff.meanLsb < 0.2, diff.nonFinite == 0};
}
bool withinImageBudget(const ImageDiff& diff) { return imageBudget(diff).within(); }

ExerciseReport& compileError(ExerciseReport& report, const Error& e) {
    report.status = CheckStatus::CompileError;
    std::string text = e.what();
    report.message = text.substr(0, text.find('\n'));
    report.details = text;
    report.hint = "fix the first error; the line after it is the line it is about";
    report.probes.clear();
    report.images.clear();
    return report;
}

// The ray tracer of the check scenes: without the teaching views where the
// course's 09 traces (a third less code for LLVM, the same picture;
// Purpose::Probe, one program for every check scene, so none is passed).
ShaderProgram checkRayTracer(const Implementation& impl) {
    return buildRayTracer(impl, definesFor(Scene{}, implementationFacts(impl), Purpose::Probe));
}

// `portable`: the student's files already compiled as GLSL ES without an
// error (checkExercises(): all of them in one program), so this check's own
// GLSL ES compile is left out. Runs in the current GL context.
ProbeStage probeStage(const ExerciseInfo& exercise, const fs::path& file, const CheckOptions& options,
                      bool portable) {
    ProbeStage stage;
    ExerciseReport& report = stage.report;
    report.number = exercise.number;
    report.id = exercise.id;
    stage.final = true;  // until the probes have run
    while (gl::GetError() != GL_NO_ERROR) {  // nothing of the exercise before reaches this one's checks
    }
    const Implementation impl = checkCompanions(exercise, file, options);
    ShaderProgram probe;
    setPhase("compiling");
    try {
        AssembledSource vertex = assembleShader("fullscreen.vert", impl, {});
        // Only this exercise's functions in the probe: the compiler drops the rest.
        ShaderDefines only{{"RL_PROBE_EXERCISE", std::to_string(exercise.number)}};
        probe = ShaderProgram(vertex, assembleShader("probe.frag", impl, only));
    } catch (const Error& e) {  // ShaderError (compile/link) or a refused file or include
        compileError(report, e);
        return stage;
    }
    // Portable GLSL: the same files as GLSL ES 3.00, which stricter drivers
    // and browsers compile; a COMPILE ERROR marked "portability error" (docs/decisions.md).
    if (std::string errors = portable ? "" : portabilityErrors(assembleShader("main.frag", impl, {}, GlslDialect::Es300));
        !errors.empty()) {
        report.status = CheckStatus::CompileError;
        report.message = errors.substr(0, errors.find('\n'));
        report.details = errors;
        report.hint = kPortabilityHint;
        return stage;
    }

    Scene scene = probeScene();
    std::vector<std::pair<std::string, ProbeOutcome>> outcomes;
    for (const ProbeSpec& spec : probesForExercise(exercise.number)) {
        setPhase(std::string("running the probe ") + spec.name);
        std::vector<std::array<float, 4>> raw = runProbe(probe, spec, spec.needsScene ? &scene : nullptr);
        std::vector<float> alpha;
        for (const auto& texel : raw) alpha.push_back(texel[3]);
        if (int loop = trippedLoop(alpha)) {
            // Name the kind of input it ran away on, and that kind's hint.
            const std::size_t k = std::size_t(std::find_if(alpha.begin(), alpha.end(), [](float a) { return a < 0; }) -
                                              alpha.begin());
            const std::string group = k < spec.cases.size() ? spec.cases[k].group : "";
            loopTimeout(report, probe, loop,
                        "for one input of " + spec.name + (group.empty() ? "" : " (" + group + ")"));
            for (const auto& [name, hint] : spec.groupHints)
                if (name == group) report.hint = hint;
            return stage;
        }
        outcomes.emplace_back(spec.signature, evaluateProbe(spec, raw));
    }
    bool allStub = std::all_of(outcomes.begin(), outcomes.end(), [](const auto& o) { return o.second.allStub; });
    if (allStub) {
        report.status = CheckStatus::NotStarted;
        report.message = "every function still returns NOT_STARTED";
        report.hint = "start with the handout: " + exercise.handout();
        return stage;
    }
    std::string table;
    for (const auto& [signature, outcome] : outcomes) {
        report.probes.push_back(outcome.summary);
        if (outcome.summary.passed == outcome.summary.total) continue;
        if (outcome.allStub) {  // one function done, this one not yet
            std::string line = outcome.summary.name + " is not started: it still returns NOT_STARTED";
            if (report.message.empty()) {
                report.message = line;
                report.hint = "finish every function of the exercise: " + exercise.handout();
            }
            table += "  " + signature + ": not started (returns NOT_STARTED)\n";
            continue;
        }
        if (report.message.empty()) {
            report.message = outcome.firstFailure;
            report.hint = outcome.hint;
        }
        table += outcome.table;
    }
    report.details = table;
    const bool probesPass = std::all_of(report.probes.begin(), report.probes.end(),
                                        [](const ProbeSummary& p) { return p.passed == p.total; });
    report.status = probesPass ? CheckStatus::Pass : CheckStatus::Fail;  // the image stage decides the rest
    stage.final = options.probesOnly;  // the probes alone need no ray tracer
    return stage;
}

// Images: this exercise from the student, every other from solutions/ (from
// the student too in a student edition: checkCompanions()). A scene in
// `shared` (by index) takes the whole submission's picture instead of this
// exercise's own ray tracer, which is compiled only when a scene needs it.
ExerciseReport imageStage(ProbeStage stage, const ExerciseInfo& exercise, const fs::path& file,
                          const CheckOptions& options, const std::vector<CheckScene>& scenes,
                          const std::map<std::size_t, SharedPicture>& shared = {}) {
    ExerciseReport& report = stage.report;
    while (gl::GetError() != GL_NO_ERROR) {  // nothing drawn before reaches this exercise's pictures
    }
    const bool probesPass = report.status == CheckStatus::Pass;
    std::string table = report.details;
    std::optional<ShaderProgram> program;
    GlRenderer renderer;
    fs::path outDir = options.outputDir / exercise.id;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const CheckScene& c = scenes[i];
        ImageSummary s;
        s.scene = c.name;
        ImageDiff diff;
        auto whole = shared.find(i);
        if (whole != shared.end()) {
            diff = whole->second.diff;
            s.gotPng = whole->second.gotPng;
            s.diffPng = whole->second.diffPng;
        } else {
            if (!program) {
                setPhase("compiling the ray tracer");
                try {
                    program = checkRayTracer(checkCompanions(exercise, file, options));
                } catch (const Error& e) {
                    return compileError(report, e);
                }
            }
            setPhase("rendering the check scene " + c.name);
            renderer.setScene(c.scene);
            renderer.draw(*program, frameFromScene(c.scene));
            if (int loop = trippedLoopInFramebuffer(renderer.framebuffer(), 1, renderer.width(), renderer.height()))
                return loopTimeout(report, *program, loop, "in one pixel of the check scene " + c.name);
            Rendering got = renderer.readBack();
            diff = compareRenderings(got, c.reference);
            if (!withinImageBudget(diff) || options.writeAllImages) {
                std::error_code ec;
                fs::create_directories(outDir, ec);
                s.gotPng = imagePath(outDir, c.name, "got");
                s.diffPng = imagePath(outDir, c.name, "diff");
                writePng(s.gotPng, got.display);
                writePng(s.diffPng, differenceHeatMap(got.display, c.reference.display));
            }
        }
        s.offFraction = diff.offFraction;
        s.meanLsb = diff.meanLsb;
        s.nonFinite = diff.nonFinite;
        const ImageBudget budget = imageBudget(diff);
        s.passed = budget.within();
        if (!s.passed || options.writeAllImages) {
            s.expectedPng = imagePath(outDir, c.name, "expected");
            if (options.writeExpectedImages) {
                std::error_code ec;
                fs::create_directories(outDir, ec);
                writePng(s.expectedPng, c.reference.display);
            }
        }
        if (!s.passed) {
            // Each budget with its number and whether this image is over it.
            char line[320];
            std::snprintf(line, sizeof line,
                          "  image %s: %.2f%% of pixels off by more than 1/255 (budget 0.5%%: %s), mean error %.2f/255 "
                          "(budget 0.2/255: %s)%s\n",
                          c.name.c_str(), 100 * diff.offFraction, budget.pixelsOk ? "within" : "OVER", diff.meanLsb,
                          budget.meanOk ? "within" : "OVER",
                          budget.finite ? "" : (", " + std::to_string(diff.nonFinite) + " NaN/Inf values (budget 0: OVER)").c_str());
            table += line;
            table += "    expected " + s.expectedPng + "\n    got      " + s.gotPng + "\n    diff     " + s.diffPng + "\n";
            if (report.message.empty()) {
                report.message = std::string(line + 2);
                report.message.pop_back();
                report.hint = "the probes pass but the picture differs: compare " + s.gotPng + " with " + s.expectedPng;
            }
        }
        report.images.push_back(s);
    }
    report.details = table;
    report.status = probesPass && report.imageFraction() == 1.0 ? CheckStatus::Pass : CheckStatus::Fail;
    return report;
}

// One exercise's whole check (checkExercise()'s child, or in-process).
ExerciseReport runChecks(const ExerciseInfo& exercise, const fs::path& file, const CheckOptions& options,
                         const std::vector<CheckScene>& scenes) {
    fastShaderCompiles();
    auto context = createHeadlessContext(parseBackend(options.backend));
    ProbeStage stage = probeStage(exercise, file, options, false);
    return stage.final ? stage.report : imageStage(std::move(stage), exercise, file, options, scenes);
}

// The files of a check of every exercise in `own` at once: theirs from the
// student, the rest as a check has them (checkCompanions()).
Implementation withOwnFiles(const std::vector<const ExerciseInfo*>& own, const CheckOptions& options) {
    Implementation impl = checkCompanions(*own.front(), exerciseFile(*own.front(), options), options);
    for (const ExerciseInfo* e : own) impl.overrides[e->file()] = exerciseFile(*e, options);
    return impl;
}

// The check scenes drawn once with the student's files of `inWhole` (every
// other from the companions, as a check has them): those within the budget,
// by index, their got/diff PNGs written once to <outputDir>/all-files/ when
// asked (grading: OUT/<id>/images/all-files/).
// None when the program does not compile or a loop runs away (each exercise
// then draws its own, which says why).
std::map<std::size_t, SharedPicture> wholeSubmissionPictures(const std::vector<const ExerciseInfo*>& inWhole,
                                                             const CheckOptions& options,
                                                             const std::vector<CheckScene>& scenes) {
    std::map<std::size_t, SharedPicture> pictures;
    if (inWhole.size() < 2) return pictures;  // one exercise: its own ray tracer is the same program
    ShaderProgram program;
    setPhase("compiling the ray tracer of every file");
    try {
        program = checkRayTracer(withOwnFiles(inWhole, options));
    } catch (const Error&) {
        while (gl::GetError() != GL_NO_ERROR) {
        }
        return pictures;
    }
    GlRenderer renderer;
    const fs::path outDir = options.outputDir / "all-files";
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const CheckScene& c = scenes[i];
        setPhase("rendering the check scene " + c.name + " with every file");
        renderer.setScene(c.scene);
        renderer.draw(program, frameFromScene(c.scene));
        if (trippedLoopInFramebuffer(renderer.framebuffer(), 1, renderer.width(), renderer.height())) return {};
        Rendering got = renderer.readBack();
        SharedPicture p;
        p.diff = compareRenderings(got, c.reference);
        if (!withinImageBudget(p.diff)) continue;
        if (options.writeAllImages) {
            std::error_code ec;
            fs::create_directories(outDir, ec);
            p.gotPng = imagePath(outDir, c.name, "got");
            p.diffPng = imagePath(outDir, c.name, "diff");
            writePng(p.gotPng, got.display);
            writePng(p.diffPng, differenceHeatMap(got.display, c.reference.display));
        }
        pictures[i] = p;
    }
    return pictures;
}

}  // namespace

std::vector<ExerciseReport> checkExercises(const std::vector<const ExerciseInfo*>& exercises,
                                           const CheckOptions& options, const std::vector<CheckScene>& scenes) {
    if (!hasSolutions()) shippedStubFolder();  // made here, not in the child (removed when this process ends)
    std::vector<ExerciseReport> reports(exercises.size());
    std::vector<std::size_t> checked;  // those a check runs for
    for (std::size_t k = 0; k < exercises.size(); ++k) {
        if (auto report = withoutCheck(*exercises[k], exerciseFile(*exercises[k], options)))
            reports[k] = *report;
        else
            checked.push_back(k);
    }
    if (options.isolate && checked.size() > 1) {
        // One child for all of them, in two rounds: every exercise's probes
        // (a file that is slow or runs away shows there, before any picture),
        // then the check scenes, drawn once with every file whose probes pass
        // (wholeSubmissionPictures()) and by an exercise's own ray tracer only
        // where that picture is not within the budget. What the child has
        // done is kept in a scratch file after each step (renamed into place,
        // so a killed child leaves the last whole state): when it dies while
        // probing an exercise, that exercise is checked in its own child and
        // the others in a new shared child with the probes they passed kept;
        // after a second death, or one while drawing, the rest are checked
        // each in its own child, as checkExercise() does.
        std::error_code ec;
        fs::create_directories(options.outputDir, ec);
        const fs::path progress = options.outputDir / ".checked-so-far.json";
        std::map<std::size_t, ExerciseReport> probed;  // probe stage done, images not (index in `exercises`)
        std::vector<std::size_t> pending = checked;
        for (int deaths = 0; !pending.empty() && deaths < 2 && !interruptRequested();) {
            fs::remove(progress, ec);
            auto work = [&]() {
                json state = {{"probed", json::object()}, {"done", json::object()}};
                auto keep = [&](const char* what, std::size_t k, const ExerciseReport& report) {
                    state[what][std::to_string(k)] = toJson(report);
                    {
                        std::ofstream out(progress.string() + ".new", std::ios::binary | std::ios::trunc);
                        out << state.dump();
                    }
                    std::error_code renamed;
                    fs::rename(progress.string() + ".new", progress, renamed);
                };
                auto seconds = [](std::chrono::steady_clock::time_point start) {
                    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                };
                setPhase("starting the OpenGL context");
                fastShaderCompiles();
                auto context = createHeadlessContext(parseBackend(options.backend));
                // Every checked file of the student in one GLSL ES program: where it
                // compiles, so does each check's (its file with the others' from
                // solutions/, which are portable, and a clash between files is the
                // desktop compile's error first), and those compiles are left out.
                // Any error, in any file: each check compiles its own, as before,
                // so that the error is reported by the exercise it belongs to.
                bool portable = false;
                if (!options.probesOnly) {
                    try {
                        std::vector<const ExerciseInfo*> own;
                        for (std::size_t k : pending) own.push_back(exercises[k]);
                        portable = portabilityErrors(assembleShader("main.frag", withOwnFiles(own, options), {}, GlslDialect::Es300)).empty();
                    } catch (const Error&) {  // a refused file or include: each check says so itself
                        portable = false;
                    }
                    while (gl::GetError() != GL_NO_ERROR) {
                    }
                }
                std::map<std::size_t, ProbeStage> stages;  // waiting for their images
                for (std::size_t k : pending) {
                    auto known = probed.find(k);
                    if (known != probed.end()) {
                        stages[k] = ProbeStage{known->second, false};
                        continue;
                    }
                    const auto start = std::chrono::steady_clock::now();
                    ProbeStage stage = probeStage(*exercises[k], exerciseFile(*exercises[k], options), options, portable);
                    stage.report.seconds = seconds(start);
                    keep(stage.final ? "done" : "probed", k, stage.report);
                    if (!stage.final) stages[k] = std::move(stage);
                }
                std::vector<const ExerciseInfo*> inWhole;
                for (const auto& [k, stage] : stages)
                    if (stage.report.status == CheckStatus::Pass) inWhole.push_back(exercises[k]);
                const std::map<std::size_t, SharedPicture> pictures = wholeSubmissionPictures(inWhole, options, scenes);
                for (auto& [k, stage] : stages) {
                    const auto start = std::chrono::steady_clock::now();
                    const bool inPictures = stage.report.status == CheckStatus::Pass;
                    ExerciseReport report = imageStage(std::move(stage), *exercises[k], exerciseFile(*exercises[k], options),
                                                       options, scenes, inPictures ? pictures : std::map<std::size_t, SharedPicture>{});
                    report.seconds += seconds(start);
                    keep("done", k, report);
                }
                return state.dump();
            };
            IsolationLimits limits;
            limits.timeoutSeconds = options.timeoutSeconds;  // one exercise's: a normal submission takes a few seconds
            IsolatedResult result = runIsolated(work, limits);
            const bool finished = result.outcome == IsolatedResult::Outcome::Finished;
            json state;
            try {
                state = finished ? json::parse(result.output)
                        : fs::exists(progress, ec) ? json::parse(readRegularFile(progress, std::uintmax_t(1) << 30))
                                                   : json::object();
            } catch (const std::exception&) {  // unreadable: every one again
                state = json::object();
            }
            fs::remove(progress, ec);
            auto recorded = [&](const char* what, std::size_t k) -> const json* {
                if (!state.is_object() || !state.contains(what) || !state[what].is_object()) return nullptr;
                auto it = state[what].find(std::to_string(k));
                return it == state[what].end() ? nullptr : &*it;
            };
            std::vector<std::size_t> left;
            for (std::size_t k : pending) {
                if (const json* done = recorded("done", k)) {
                    reports[k] = reportFromJson(*done);
                    continue;
                }
                if (const json* stage = recorded("probed", k)) probed[k] = reportFromJson(*stage);
                left.push_back(k);
            }
            pending = left;
            if (finished || pending.empty()) break;  // a finished child left nothing: each in its own child
            ++deaths;
            // Died while probing: that exercise in its own child, a new shared child for the rest.
            auto probing = std::find_if(pending.begin(), pending.end(), [&](std::size_t k) { return !probed.count(k); });
            if (probing == pending.end()) break;  // died drawing: each in its own child
            if (interruptRequested()) break;
            reports[*probing] = checkExercise(*exercises[*probing], options, scenes);
            pending.erase(probing);
        }
        checked = pending;
    }
    for (std::size_t k : checked) {
        if (interruptRequested()) break;  // Ctrl-C: the caller discards what is left (grading throws Interrupted)
        reports[k] = checkExercise(*exercises[k], options, scenes);
    }
    return reports;
}

ExerciseReport checkExercise(const ExerciseInfo& exercise, const CheckOptions& options,
                             const std::vector<CheckScene>& scenes) {
    // Made here, not in the child, so that it is removed when this process ends.
    if (!hasSolutions()) shippedStubFolder();
    ExerciseReport report;
    report.number = exercise.number;
    report.id = exercise.id;
    const fs::path file = exerciseFile(exercise, options);
    if (auto early = withoutCheck(exercise, file)) return *early;
    auto work = [&]() {
        setPhase("starting the OpenGL context");
        return toJson(runChecks(exercise, file, options, scenes)).dump();
    };
    if (!options.isolate) {
        try {
            report = reportFromJson(json::parse(work()));
        } catch (const Error& e) {
            report.status = CheckStatus::Crashed;
            report.message = e.what();
        }
        return report;
    }
    IsolationLimits limits;
    limits.timeoutSeconds = options.timeoutSeconds;
    IsolatedResult result = runIsolated(work, limits);
    const std::string& phase = result.phase;  // what the child was doing when it ended
    const std::string name = file.filename().string();
    if (result.outcome == IsolatedResult::Outcome::Finished) {
        try {
            report = reportFromJson(json::parse(result.output));
        } catch (const json::exception&) {
            report.status = CheckStatus::Crashed;
            report.message = "the check's child process returned no result";
        }
    } else if (result.outcome == IsolatedResult::Outcome::TimedOut && phase.rfind("compiling", 0) == 0) {
        // The compiler, not the shader: every loop is bounded, so this is code
        // the driver cannot compile in time (a loop it unrolls, a huge function).
        report.status = CheckStatus::TimedOut;
        report.message = "the check " + result.reason + " while the driver was still compiling " + name +
                         " (compiler time): the file is more code than a shader compiler handles";
        report.hint = "look for a loop with a large constant bound (compilers unroll them) or very long code";
    } else if (result.outcome == IsolatedResult::Outcome::TimedOut) {
        report.status = CheckStatus::TimedOut;
        const bool shaderRunning = phase.rfind("running", 0) == 0 || phase.rfind("rendering", 0) == 0;
        report.message = "the check " + result.reason + " while " + (phase.empty() ? "running" : phase) +
                         (shaderRunning ? " (shader time): " + name + " does too much work per pixel" : " (time)");
        report.hint = "every loop is bounded at " + std::to_string(kLoopLimit) +
                      " iterations per pixel; look for a loop that does heavy work each time round";
    } else if (result.outcome == IsolatedResult::Outcome::OutOfMemory) {
        report.status = CheckStatus::Crashed;
        report.message = "the check ran out of memory while " + (phase.empty() ? "running" : phase) + " (memory): " +
                         name + " needs more than the " + std::to_string(limits.memoryBytes >> 30) + " GiB allowed";
        report.hint = "look for large arrays or code the compiler expands";
    } else {
        report.status = CheckStatus::Crashed;
        report.message = "the check " + result.reason + " while " + (phase.empty() ? "running" : phase);
        report.hint = "the driver or the check failed while running " + name;
    }
    report.seconds = result.seconds;
    return report;
}

std::optional<ExerciseReport> checkTogether(const CheckOptions& options) {
    Implementation impl{options.implDir, {}};
    for (const auto& [number, file] : options.fileOverride)
        impl.overrides[findExercise(std::to_string(number)).file()] = file;
    std::error_code ec;
    for (const ExerciseInfo& e : allExercises())
        if (!fs::is_regular_file(impl.fileFor(e.file()), ec)) return std::nullopt;
    ExerciseReport report;
    report.id = "all files";
    auto work = [&]() {
        json j = {{"error", ""}};
        try {
            auto context = createHeadlessContext(parseBackend(options.backend));
            buildRayTracer(impl);
        } catch (const Error& e) {  // ShaderError, a refused file or include
            j["error"] = e.what();
        }
        return j.dump();
    };
    auto verdict = [&](const std::string& error) {
        report.status = error.empty() ? CheckStatus::Pass : CheckStatus::CompileError;
        report.message = error.substr(0, error.find('\n'));
        report.details = error;
        if (!error.empty())
            report.hint = "raylab render compiles the ten files into one shader, as this step does";
    };
    if (!options.isolate) {
        verdict(json::parse(work()).value("error", ""));
        return report;
    }
    IsolationLimits limits;
    limits.timeoutSeconds = options.timeoutSeconds;
    IsolatedResult result = runIsolated(work, limits);
    report.seconds = result.seconds;
    if (result.outcome == IsolatedResult::Outcome::Finished) {
        try {
            verdict(json::parse(result.output).value("error", ""));
            return report;
        } catch (const json::exception&) {
        }
    }
    report.status = result.outcome == IsolatedResult::Outcome::TimedOut ? CheckStatus::TimedOut : CheckStatus::Crashed;
    report.message = "compiling the ten files together " + (result.reason.empty() ? "failed" : result.reason);
    return report;
}

std::map<int, bool> exercisesCalled(const ExerciseInfo& exercise, const Implementation& impl) {
    // Each exercise's function names, as its shipped stub declares them.
    static const std::vector<std::pair<int, std::vector<std::string>>> declared = [] {
        std::vector<std::pair<int, std::vector<std::string>>> out;
        for (const ExerciseInfo& e : allExercises()) {
            std::vector<std::string> names;
            if (const std::string* stub = shippedStub(e.file()))
                for (const GlslFunction& f : scanGlsl(*stub).functions) names.push_back(f.name);
            out.emplace_back(e.number, names);
        }
        return out;
    }();
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    constexpr std::uintmax_t kLargestExercise = 1 << 20;  // as the checks read an exercise file
    std::map<int, bool> called;  // exercise number -> called by the files themselves (else through the framework)
    std::vector<int> todo{exercise.number};
    auto add = [&](int number, bool direct) {
        if (number == exercise.number || called.count(number)) return;
        called[number] = direct;
        todo.push_back(number);
    };
    while (!todo.empty()) {
        const ExerciseInfo& caller = findExercise(std::to_string(todo.back()));
        todo.pop_back();
        // What the unit declares: the functions each of its functions builds on
        // ("needs") and those the framework calls for it ("framework_calls":
        // the intersection and the shading behind a bounce).
        for (const ExerciseFunction& f : caller.functions) {
            for (const std::string& name : f.needs)
                if (const ExerciseInfo* owner = exerciseOfFunction(name); owner && owner->inCourse) add(owner->number, true);
            for (const std::string& name : f.frameworkCalls)
                if (const ExerciseInfo* owner = exerciseOfFunction(name); owner && owner->inCourse) add(owner->number, false);
        }
        std::string code;
        try {
            code = std::regex_replace(readRegularFile(impl.fileFor(caller.file()), kLargestExercise), comments, " ");
        } catch (const Error&) {
            continue;  // a missing or unreadable file calls nothing; its check says why
        }
        for (const auto& [number, names] : declared) {
            if (number == exercise.number || number == caller.number || called.count(number)) continue;
            for (const std::string& name : names)
                if (std::regex_search(code, std::regex("\\b" + name + "\\s*\\("))) {
                    add(number, true);
                    break;
                }
        }
    }
    return called;
}

Implementation checkCompanions(const ExerciseInfo& exercise, const fs::path& file, const CheckOptions& options) {
    if (hasSolutions()) return Implementation{solutionsDir(), {{exercise.file(), file}}};
    Implementation own{options.implDir, {}};
    std::error_code ec;
    for (const ExerciseInfo& e : allExercises()) {
        auto it = options.fileOverride.find(e.number);
        if (it != options.fileOverride.end())
            own.overrides[e.file()] = it->second;
        else if (!fs::is_regular_file(options.implDir / e.file(), ec))
            own.overrides[e.file()] = shippedStubFolder() / e.file();
    }
    own.overrides[exercise.file()] = file;
    if (!options.probesOnly) return own;
    // The probes: the student's files in ownFiles, the shipped stubs for the rest.
    Implementation probes{shippedStubFolder(), {{exercise.file(), file}}};
    for (int number : options.ownFiles) {
        const std::string name = findExercise(std::to_string(number)).file();
        if (number != exercise.number) probes.overrides[name] = own.fileFor(name);
    }
    return probes;
}

std::map<int, ExerciseReport> checkProbesOfAll(const CheckOptions& options, const std::vector<CheckScene>& scenes) {
    CheckOptions probesOnly = options;
    probesOnly.probesOnly = true;
    probesOnly.ownFiles.clear();
    std::map<int, ExerciseReport> first;
    for (const ExerciseInfo& e : allExercises()) {  // the teaching order: each builds on the ones before it
        first[e.number] = checkExercise(e, probesOnly, scenes);
        if (first[e.number].status == CheckStatus::Pass) probesOnly.ownFiles.insert(e.number);
    }
    return first;
}

ExerciseReport checkWithOwnFiles(const ExerciseInfo& exercise, const CheckOptions& options,
                                 const std::vector<CheckScene>& scenes, const std::map<int, ExerciseReport>& firstPass) {
    auto passes = [&](int number) {
        auto it = firstPass.find(number);
        return it != firstPass.end() && it->second.status == CheckStatus::Pass;
    };
    auto own = firstPass.find(exercise.number);
    if (own == firstPass.end()) return checkExercise(exercise, options, scenes);
    ExerciseReport report = own->second;
    if (report.status == CheckStatus::Pass) {
        for (const ExerciseInfo& e : allExercises())
            if (e.number != exercise.number && !passes(e.number)) {
                report.imagesWaitingFor = e.id;
                return report;
            }
        return checkExercise(exercise, options, scenes);
    }
    if (report.status == CheckStatus::Fail) {
        // A failure may come from an exercise this one calls, which the stub
        // stood in for: name the first of them in the course's order, only
        // one it calls (its file, or the framework for it), never one it
        // merely follows.
        auto it = options.fileOverride.find(exercise.number);
        const fs::path file = it != options.fileOverride.end() ? it->second : options.implDir / exercise.file();
        std::string waiting;
        const std::map<int, bool> called = exercisesCalled(exercise, checkCompanions(exercise, file, options));
        for (const ExerciseInfo& e : allExercises()) {
            auto c = called.find(e.number);
            if (c != called.end() && !passes(e.number) && waiting.empty())
                waiting = "it calls exercise " + e.id + (c->second ? "" : " (through the framework)");
        }
        if (!waiting.empty())
            report.hint = waiting + ", whose probes do not pass yet (its stub stood in for it): make that one pass " +
                          "first; " + report.hint;
    }
    return report;
}

std::string formatReport(const ExerciseReport& r, bool verbose) {
    char head[64];
    std::snprintf(head, sizeof head, "%-17s %-13s ", r.id.c_str(), statusName(r.status).c_str());
    std::string out = head;
    if (r.status == CheckStatus::Pass) {
        int cases = 0;
        for (const auto& p : r.probes) cases += p.total;
        out += std::to_string(cases) + " probe cases, " +
               (r.imagesWaitingFor.empty() ? std::to_string(r.images.size()) + " images"
                                           : "images waiting for exercise " + r.imagesWaitingFor);
    } else {
        out += r.message;
    }
    out += "\n";
    if (r.status != CheckStatus::Pass) {
        if (!r.hint.empty()) out += "    hint: " + r.hint + "\n";
        if (!r.details.empty() && (verbose || r.status == CheckStatus::CompileError || r.status == CheckStatus::Fail)) {
            std::istringstream lines(r.details);
            std::string line;
            while (std::getline(lines, line)) out += "    " + line + "\n";
        }
    }
    return out;
}

}  // namespace rl
