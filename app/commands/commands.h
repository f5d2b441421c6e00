// The subcommands of `raylab`, each a thin layer over the library. Each
// add*Command registers its options and callback on the CLI11 app.
#pragma once

#include "core/scene.h"

#include <CLI/CLI.hpp>

#include <string>

namespace rl {

void addRenderCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addGradeCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addRecordCommand(CLI::App& app);
void addCourseCommand(CLI::App& app);

// The course's table as the documents show it (raylab course --markdown),
// handout links relative to the repository folder `from` ("" = the root).
std::string courseMarkdownTable(const std::string& from);

// Shared option parsing (app/commands/options.cpp).
struct Size {
    int width = 0, height = 0;
};
Size parseSize(const std::string& text);  // "640x480"; throws rl::Error "--size: ..."

// The scene a command renders: the file (or the embedded default scene when
// `path` is empty), its warnings printed as "raylab: warning: ...", and the
// --size override when `size` is not empty.
Scene sceneForCommand(const std::string& path, const std::string& size);

// Validators for option values. CLI11 reports a failure as a usage error,
// "--spp: must be ..., not '0'" (one line, exit status 2, see main.cpp). Each
// refuses an empty value, text that is not a number, NaN and infinities, and
// values out of range; CLI11's own conversion would turn '' into 0 silently.
CLI::Validator wholeNumberIn(long long min, long long max);
CLI::Validator squareNumberIn(long long min, long long max);  // spp: 1, 4, 9, 16, ...
CLI::Validator secondsIn(double minExclusive, double max);     // --timeout: (0, max]
CLI::Validator numberIn(double min, double max);
CLI::Validator sizeValue();  // WIDTHxHEIGHT, as parseSize
CLI::Validator notEmpty();   // a path or a name

}  // namespace rl
