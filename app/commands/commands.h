// The subcommands of `raylab`, each a thin layer over the library. Each
// add*Command registers its options and callback on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace rl {

void addRenderCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addGradeCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addRecordCommand(CLI::App& app);

// Shared option parsing.
struct Size {
    int width = 0, height = 0;
};
Size parseSize(const std::string& text);  // "640x480"; throws rl::Error

}  // namespace rl
