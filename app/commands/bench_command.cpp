// raylab bench [SCENE...] [--csv FILE] [--plot FILE] [--markdown FILE] [--size WxH] [--warmup N]
//              [--frames N] [--compiles N] [--yardstick FILE]... [--reference-spp N] [--sweeps LIST] [--backend B] [--clock C] [--impl DIR]
// Time per frame against error for every variant and setting
// (app/bench/bench.h), as a table, a CSV and an SVG plot with the Pareto front.
#include "commands/commands.h"

#include "bench/bench.h"
#include "bench/outside.h"
#include "bench/view_bench.h"
#include "core/error.h"
#include "core/message.h"
#include "core/file_io.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace rl {
namespace {

struct BenchCommandOptions {
    std::vector<std::string> scenes;
    std::string csv;
    std::string plot;
    std::string markdown;
    std::string size = "320x240";
    int warmup = 2;
    int compiles = 3;
    int frames = 5;
    int referenceSpp = 16;
    int environmentSamples = bench::kExactReferenceSamples;
    std::string sweeps;
    std::string backend = "auto";
    std::string clock = "auto";
    std::string impl;
    std::vector<std::string> yardsticks;
    std::vector<std::string> alsoImpls;
    std::string pictures;
    bool sizeGiven = false;  // --size on the command line (the view sweep's default is 1280x720)
};

std::set<std::string> splitList(const std::string& text) {
    std::set<std::string> out;
    std::stringstream s(text);
    std::string item;
    while (std::getline(s, item, ','))
        if (!item.empty()) out.insert(item);
    return out;
}

// The command as it was run (every option that differs from its default), for
// the --markdown section, so that the document says how to regenerate it.
std::string commandLine(const BenchCommandOptions& o) {
    BenchCommandOptions defaults;
    std::string line = "./raylab bench";
    for (const std::string& scene : o.scenes) line += " " + scene;
    auto option = [&](const char* name, const std::string& value, const std::string& fallback) {
        if (value != fallback) line += std::string(" ") + name + " " + value;
    };
    option("--size", o.size, defaults.size);
    option("--sweeps", o.sweeps, defaults.sweeps);
    option("--clock", o.clock, defaults.clock);
    option("--warmup", std::to_string(o.warmup), std::to_string(defaults.warmup));
    option("--frames", std::to_string(o.frames), std::to_string(defaults.frames));
    option("--compiles", std::to_string(o.compiles), std::to_string(defaults.compiles));
    option("--reference-spp", std::to_string(o.referenceSpp), std::to_string(defaults.referenceSpp));
    option("--environment-samples", std::to_string(o.environmentSamples), std::to_string(defaults.environmentSamples));
    option("--backend", o.backend, defaults.backend);
    option("--impl", o.impl, defaults.impl);
    for (const std::string& file : o.yardsticks) line += " --yardstick " + file;
    for (const std::string& dir : o.alsoImpls) line += " --also-impl " + dir;
    option("--csv", o.csv, defaults.csv);
    option("--plot", o.plot, defaults.plot);
    option("--markdown", o.markdown, defaults.markdown);
    option("--pictures", o.pictures, defaults.pictures);
    return line;
}

void runBenchCommand(const BenchCommandOptions& o) {
    if (!o.csv.empty()) requireOutputPath(o.csv);
    if (!o.plot.empty()) requireOutputPath(o.plot);
    if (!o.markdown.empty()) {
        requireOutputPath(o.markdown);
        // minutes of measuring must not end in a refusal
        bench::checkMarkdownTarget(o.markdown, bench::markdownSectionName(splitList(o.sweeps)));
    }
    bench::Options options;
    options.scenes = o.scenes;
    Size size = parseSize(o.size);
    options.width = size.width;
    options.height = size.height;
    options.warmup = o.warmup;
    options.compiles = o.compiles;
    options.frames = o.frames;
    options.referenceSpp = o.referenceSpp;
    options.environmentSamples = o.environmentSamples;
    options.sweeps = splitList(o.sweeps);
    options.backend = o.backend;
    options.implDir = o.impl;
    if (!o.pictures.empty()) {
        if (!std::filesystem::is_directory(o.pictures)) throw Error("--pictures: " + o.pictures + " is not a directory");
        options.picturesDir = o.pictures;
    }
    for (const std::string& dir : o.alsoImpls) {
        if (!std::filesystem::is_directory(dir)) throw Error("--also-impl: " + dir + " is not a directory");
        options.alsoImpls.push_back(dir);
    }
    for (const std::string& file : o.yardsticks) {
        readRegularFile(file, bench::kOutsideShaderMaxBytes, "yardstick shader");  // before minutes of measuring
        options.yardsticks.push_back(file);
    }
    if (o.clock == "auto") options.clock = bench::Clock::Auto;
    else if (o.clock == "gpu") options.clock = bench::Clock::Gpu;
    else if (o.clock == "wall") options.clock = bench::Clock::Wall;
    else if (o.clock == "cpu") options.clock = bench::Clock::Cpu;
    else throw Error("--clock: expected auto, gpu, wall or cpu, not " + quotedValue(o.clock));

    // "view" (bench/view_bench.h) is its own table: the live view's programs
    // against the generic one at lecture size, not a row of the error sweep.
    const bool viewSweep = options.sweeps.erase("view") > 0;
    for (const std::string& group : options.sweeps)  // before minutes of the view sweep
        if (std::find(bench::sweepNames().begin(), bench::sweepNames().end(), group) == bench::sweepNames().end())
            throw Error("--sweeps: unknown group " + quotedValue(group) +
                        " (expected modes, layers, bounces, spp, resolution, models, strategies, environment or view)");
    if (viewSweep) {
        bench::Options view = options;
        if (!o.sizeGiven) {
            view.width = bench::kViewBenchWidth;
            view.height = bench::kViewBenchHeight;
        }
        std::cout << bench::formatViewBench(bench::runViewBench(view, std::cerr));
        if (options.sweeps.empty()) return;  // only the view sweep was asked for
    }
    std::string context;
    std::string load = bench::loadAverage();  // before the run: what the machine was doing besides
    std::vector<bench::Measurement> results = bench::runBench(options, std::cerr, &context);
    std::cout << bench::formatTable(results) << "\n" << bench::formatComparisons(results);
    const std::string environment = bench::formatEnvironmentTable(results);
    if (!environment.empty()) std::cout << "\n" << environment;
    if (!o.csv.empty()) {
        bench::writeTextFile(o.csv, bench::toCsv(results));
        std::cout << std::filesystem::absolute(o.csv).lexically_normal().string() << "\n";
    }
    if (!o.plot.empty()) {
        bench::writeTextFile(o.plot, bench::errorTimeSvg(results));
        std::cout << std::filesystem::absolute(o.plot).lexically_normal().string() << "\n";
    }
    if (!o.markdown.empty()) {
        bench::MarkdownRun run{commandLine(o), context, load, o.plot, bench::markdownSectionName(options.sweeps)};
        bench::writeMarkdown(o.markdown, run, results);
        std::cout << std::filesystem::absolute(o.markdown).lexically_normal().string() << "\n";
    }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchCommandOptions>();
    CLI::App* cmd = app.add_subcommand("bench", "Measure time per frame against error for shader variants and settings");
    cmd->add_option("scenes", options->scenes, "Scene files (.json); scenes/lecture.json when omitted")
        ->check(notEmpty());
    cmd->add_option("--csv", options->csv, "Write one CSV row per measurement to FILE")->check(notEmpty());
    cmd->add_option("--plot", options->plot, "Write error against time, Pareto front marked, as SVG to FILE")
        ->check(notEmpty());
    cmd->add_option("--markdown", options->markdown,
                    "Write the table, the comparisons, the command and the machine as Markdown to FILE; in a file "
                    "that has the markers <!-- bench:begin --> and <!-- bench:end -->, replace only what lies between them")
        ->check(notEmpty());
    cmd->add_option("--size", options->size, "Size of every measurement and of the reference, WIDTHxHEIGHT")
        ->capture_default_str()
        ->check(sizeValue());
    cmd->add_option("--warmup", options->warmup, "Untimed frames before timing each variant")
        ->capture_default_str()
        ->check(wholeNumberIn(0, 1000));
    cmd->add_option("--frames", options->frames, "Timed frames per variant (the median is reported)")
        ->capture_default_str()
        ->check(wholeNumberIn(1, 10000));
    cmd->add_option("--yardstick", options->yardsticks,
                    "A fragment shader from outside to time beside raylab's programs (row outside:NAME); the "
                    "strongest yardstick of a run is the fastest of expert, textbook and these (docs/performance.md)")
        ->check(notEmpty());
    cmd->add_option("--also-impl", options->alsoImpls,
                    "Another folder of exercise files, timed in the modes sweep beside --impl's as the row "
                    "specialised:FOLDER (repeatable)")
        ->check(notEmpty());
    cmd->add_option("--compiles", options->compiles,
                    "Copies of each variant's program, each compiled on its own; the fastest copy is timed "
                    "(every variant alike: on llvmpipe some copies of the same code run slower)")
        ->capture_default_str()
        ->check(wholeNumberIn(1, 8));
    cmd->add_option("--reference-spp", options->referenceSpp, "Samples per pixel of the converged CPU reference")
        ->capture_default_str()
        ->check(squareNumberIn(1, 1024));
    cmd->add_option("--environment-samples", options->environmentSamples,
                    "Samples per strategy per hit of the environment sweep's exact references (fixed seeds)")
        ->capture_default_str()
        ->check(wholeNumberIn(1, 65536));
    cmd->add_option("--sweeps", options->sweeps,
                    "Comma-separated groups to run: modes, layers, bounces, spp, resolution, models, strategies, environment "
                    "(default: all; environment: scenes with an environment only, with its own --markdown section "
                    "<!-- bench-environment:begin --> when run alone); "
                    "view: the live view's programs against the generic one (1280x720 unless --size)");
    cmd->add_option("--pictures", options->pictures,
                    "Write every measured picture (PNG and PFM, <scene>-<variant>) and the environment sweep's exact "
                    "references into this existing folder, to see where an error lies");
    cmd->add_option("--backend", options->backend, "OpenGL backend: auto, egl, osmesa or glfw (a hidden window)")->capture_default_str();
    cmd->add_option("--clock", options->clock,
                    "Frame timing: gpu (GL_TIME_ELAPSED), wall (draw + glFinish), cpu (process CPU time), auto (wall on llvmpipe)")
        ->capture_default_str();
    cmd->add_option("--impl", options->impl, "Folder of exercise implementations (default: solutions/; exercises/ where there is none)")
        ->check(notEmpty());
    cmd->callback([options, cmd] {
        options->sizeGiven = cmd->count("--size") > 0;
        runBenchCommand(*options);
    });
}

}  // namespace rl
