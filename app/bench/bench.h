// `raylab bench`: GPU time per frame against error, for the ways of rendering
// a scene that raylab offers. Each measurement renders one variant (a whole-
// shader mode, a model variant, a numerical strategy) at one setting (bounce
// limit, samples per pixel, resolution), takes the median time of several
// frames after warm-up frames (GL_TIME_ELAPSED on a GPU; see Clock for
// llvmpipe) and compares the picture with a converged CPU reference of the
// same scene at the same size.
// docs/performance.md, "Speed against error (raylab bench)", shows a run.
#pragma once

#include "bench/environment_sweep.h"
#include "bench/frame_clock.h"
#include "core/image.h"
#include "core/scene.h"
#include "shader/shader_library.h"

#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rl::bench {

// What one measurement renders. The scene carries every setting (size, spp,
// bounce limit, model); the rest says how the shader is built.
struct Variant {
    std::string name;        // "specialised", "generic", "bounces=0", "spp=4", "res=1/2", "model:beckmann", ...
    std::string sweep;       // the group it belongs to: "modes", "bounces", "spp", "resolution", "models", "strategies"
    bool specialised = true; // the scene's structure compiled in (Purpose::EveryView, or Picture with `picture`)
    bool picture = true;     // without the term views (Purpose::Picture, or GenericPicture when not specialised)
    bool textbook = false;   // the straightforward yardstick instead (bench/textbook.h): none of the flags above apply
    bool expert = false;     // the expert yardstick instead (bench/expert.h): none of the flags above apply
    std::filesystem::path outside;  // non-empty: a yardstick from outside, this file (bench/outside.h)
    Scene scene;             // the scene as rendered (size already reduced for a resolution variant)
    std::vector<std::string> withoutDefines;  // defines taken out again ("RL_BOUNCE_CUTOFF")
    ShaderDefines withDefines;                // defines added (the other side of a choice: "RL_BOUNCE_CUTOFF")
    // Exercise file -> replacement (numerical strategies: naive versions of a solution function).
    std::map<std::string, std::filesystem::path> overrides;
    std::string skipReason;  // non-empty: not measured, reported with this note
    // The "environment" sweep (bench/environment_sweep.h): how the GL picture
    // approximates environment light, compared with the exact references.
    std::optional<EnvironmentApproximation> environment;
    // The row "exact:no-V": no GL program, the exact reference without
    // visibility itself, compared with the one with visibility.
    bool exactWithoutVisibility = false;
};

struct Measurement {
    std::string scene;       // scene name (file stem)
    std::string variant;
    std::string sweep;
    std::string mode;        // modeName(): "generic", "generic-picture", "specialised-full" or "specialised"
    int width = 0, height = 0;  // rendered size (the reference's size for every variant but resolution ones)
    int spp = 1;
    int maxBounces = 0;
    int frames = 0;          // timed frames
    double msMedian = 0, msMin = 0, msMax = 0;  // time per frame, by `clock`
    std::string clock;       // "gpu" (GL_TIME_ELAPSED), "wall" or "cpu" (see Clock)
    double compileMs = 0;    // building the program (compile + link), wall clock
    double firstDrawMs = 0;  // its first draw + glFinish, wall clock: llvmpipe generates the machine code there
    ImageDiff error;         // against the converged CPU reference (upscaled first for resolution variants)
    bool onFront = false;    // on the Pareto front of (msMedian, error.meanLsb) within its scene
    bool skipped = false;
    std::string note;        // why it was skipped, or how it was timed
    // Rows of the "environment" sweep: `error` is against the exact reference
    // WITH visibility, this one against the exact reference without it; the
    // samples of those references and their noise (environment_sweep.h).
    ImageDiff errorWithoutVisibility;
    int referenceSamples = 0;
    double referenceNoiseLsb = 0, referenceNoiseOffFraction = 0;
    // Computing the approximation's tables on the host (prefiltered chain,
    // split-sum table, SH9), wall clock, once per image and settings: what a
    // larger setting costs, since every row costs the same per frame.
    double tablesMs = 0;
};

struct Options {
    std::vector<std::string> scenes;  // scene files; empty: scenes/lecture.json
    int width = 320, height = 240;    // size of every measurement and of the reference
    int warmup = 2;                   // untimed frames first (llvmpipe compiles on the first draw)
    int frames = 5;                   // timed frames; the median is reported
    // Copies of each variant's program, each compiled and placed in memory on
    // its own, the fastest of which is timed (every variant alike, yardsticks
    // included): on llvmpipe one copy in ten of the very same machine code runs
    // 1.4 to 2x slower for as long as it lives (docs/performance.md, "One copy
    // in ten"), so one copy per variant made a ratio a lottery.
    int compiles = 3;
    // Yardsticks from outside (bench/outside.h): fragment shader files timed
    // in the modes sweep of every scene as rows "outside:<stem>".
    std::vector<std::filesystem::path> yardsticks;
    int referenceSpp = 16;            // samples per pixel of the converged CPU reference
    // Samples per strategy per hit of the environment sweep's exact references.
    int environmentSamples = kExactReferenceSamples;
    // Which groups to run: modes, layers, bounces, spp, resolution, models, strategies, environment (empty: all).
    // environment: only on scenes that have one.
    std::set<std::string> sweeps;
    std::string backend = "auto";
    Clock clock = Clock::Auto;        // Auto: Wall on llvmpipe and other software rasterisers, else Gpu
    std::filesystem::path implDir;    // empty: solutions/ (exercises/ where there is none)
    // More folders of exercise files, each a row "specialised:<folder>" of the
    // modes sweep beside `implDir`'s: `raylab render`'s program for those
    // files, measured in the same run (a student's own, the course's with a
    // comment added).
    std::vector<std::filesystem::path> alsoImpls;
    // Where to write every measured picture (PNG and PFM, named
    // <scene>-<variant>) and the environment sweep's exact references, to
    // see where an error lies; empty: nowhere.
    std::filesystem::path picturesDir;
};

// Every group name Options::sweeps accepts, in the order they run.
const std::vector<std::string>& sweepNames();

// The four whole-shader modes, from the flags of a Variant:
//   generic           Purpose::Generic: `raylab render --generic`
//   generic-picture   Purpose::GenericPicture: the same without the term views
//   specialised-full  Purpose::EveryView: every view, as `raylab render --view d` compiles it
//   specialised       Purpose::Picture: `raylab render`
// (render/define_table.h)
// and the two yardsticks, which have none of them: "textbook", the
// straightforward one (bench/textbook.h), and "expert", the hand-optimised
// one (bench/expert.h), the strongest: every speed ratio is against it.
std::string modeName(bool specialised, bool picture);

// The variants of one scene (already at the bench size), in table order.
// Variants that cannot run here (a model variant not in GLSL yet, a missing
// strategy file) come back with skipReason set.
std::vector<Variant> makeVariants(const Scene& scene, const Options& options);

// Runs everything (creates its own headless context); progress lines go to `log`.
// Marks each scene's Pareto front. Throws rl::Error for a bad scene file or options.
// `context`, when given, receives the GL context's description (renderer, version).
std::vector<Measurement> runBench(const Options& options, std::ostream& log, std::string* context = nullptr);

// Nearest-neighbour resampling to width x height (display and radiance), for
// comparing a lower-resolution render with the full-size reference.
Rendering resampleNearest(const Rendering& image, int width, int height);

// Marks Measurement::onFront per scene (skipped rows are never on it).
void markParetoFronts(std::vector<Measurement>& measurements);

// Whether a yardstick's picture is as right as raylab's picture program
// (`program`, the specialised row) within the budget every yardstick is held
// to: mean error at most 0.05 LSB above it and at most 0.5% more pixels off
// by over 1/255 (BenchCli.TheExpertYardstickRendersTheModelWithinTheBudget
// holds the expert to it; the ratios of issue #25 are "at equal or lower
// error"). A yardstick from outside that is beyond it does not count as
// the strongest: drawing less is not drawing faster.
bool withinYardstickBudget(const Measurement& yardstick, const Measurement& program);

// Specialised against generic at the scene's own settings, with the two
// intermediate modes that split the speed-up into its parts (null if not run).
struct ModeComparison {
    std::string scene;
    const Measurement* generic = nullptr;
    const Measurement* specialised = nullptr;
    const Measurement* genericPicture = nullptr;
    const Measurement* specialisedFull = nullptr;
    const Measurement* textbook = nullptr;  // the straightforward yardstick, when the run has it
    const Measurement* expert = nullptr;    // the expert yardstick, when the run has it
    std::vector<const Measurement*> outside;  // yardsticks from outside (--yardstick), in the run's order
    double speedup() const;  // generic ms / specialised ms
    double overTextbook() const;  // textbook ms / specialised ms (0 without the yardstick)
    // The strongest yardstick measured: the fastest of expert, textbook and
    // those from outside within the budget (withinYardstickBudget), nullptr
    // without any.
    const Measurement* strongest() const;
    double overStrongest() const;  // strongest ms / specialised ms (0 without one)
};
std::vector<ModeComparison> modeComparisons(const std::vector<Measurement>& measurements);

// Output. The CSV has one row per measurement and at least the columns
// scene, variant, width, height, ms_median, err_mean_lsb, err_p99_lsb,
// off_frac, relmse, psnr.
std::string formatTable(const std::vector<Measurement>& measurements);
std::string formatComparisons(const std::vector<Measurement>& measurements);
std::string toCsv(const std::vector<Measurement>& measurements);
void writeTextFile(const std::filesystem::path& path, const std::string& text);  // throws rl::Error

// The --markdown output: the command, the machine, the plot (a link, relative
// to the Markdown file) and the table with the comparisons, between the
// markers <!-- bench:begin --> and <!-- bench:end -->, each on a line of its
// own. An existing file with both keeps everything outside them
// (docs/performance.md, which also quotes them in its text); a new
// file gets the section alone; an existing file without them is refused
// (rl::Error), never overwritten.
struct MarkdownRun {
    std::string command;   // as run, e.g. "./raylab bench scenes/lecture.json --size 640x480 ..."
    std::string context;   // the GL context's description
    std::string load;      // the load average before the run ("" when unknown)
    std::string plot;      // the SVG written by --plot ("" for none)
    // The markers' name: "bench" (<!-- bench:begin -->), or "bench-environment"
    // for a run of the environment sweep alone (markdownSectionName()), so that
    // docs/performance.md keeps both tables.
    std::string section = "bench";
};
// "bench-environment" when `sweeps` is the environment sweep alone, else "bench".
std::string markdownSectionName(const std::set<std::string>& sweeps);
std::string markdownSection(const MarkdownRun& run, const std::vector<Measurement>& measurements,
                            const std::filesystem::path& markdownFile);
void writeMarkdown(const std::filesystem::path& file, const MarkdownRun& run,
                   const std::vector<Measurement>& measurements);
void checkMarkdownTarget(const std::filesystem::path& file, const std::string& section = "bench");  // the refusal above, before a run
std::string loadAverage();  // the three figures of /proc/loadavg, "" where there is none

// Error against time, one panel per scene, the Pareto front marked (svg_plot.cpp).
std::string errorTimeSvg(const std::vector<Measurement>& measurements);

}  // namespace rl::bench
