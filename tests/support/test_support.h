// Helpers shared by the test suites: running the raylab binary, temporary
// folders, and rendering through the library.
#pragma once

#include "core/image.h"
#include "core/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rl::test {

struct CommandResult {
    int status = -1;     // exit status
    std::string output;  // stdout and stderr together
};

// Runs `build/bin/raylab ARGS` through the shell (2>&1), with an optional
// working directory and environment prefix (e.g. "RAYLAB_ROOT=/tmp/x").
CommandResult runRaylab(const std::string& args, const std::string& env = "");

// Runs a shell command line (2>&1 appended), e.g. a command as a document writes it.
CommandResult runShell(const std::string& command);

// A fresh empty folder under the system temp directory, removed at exit.
std::filesystem::path freshTempDir(const std::string& name);

void writeText(const std::filesystem::path& path, const std::string& text);
std::string readText(const std::filesystem::path& path);

// `s` in single quotes for the shell ('\'' for each quote inside).
std::string shellQuoted(const std::string& s);

// Copies the repository into `to` as a clone would have it: the files git
// tracks (and new ones it does not ignore), from the working tree, with their
// permissions; files deleted in the working tree are left out. No build.
void copyRepositoryFiles(const std::filesystem::path& to);

// The files of kind "mutants" or "alternatives" of every exercise of the
// course (course/<unit>/<kind>/*.glsl), named "<unit>--<stem>.glsl" as test
// parameters, sorted.
std::vector<std::string> unitFileNames(const std::string& kind);
// The file such a name stands for: course/<unit>/<kind>/<stem>.glsl.
std::filesystem::path unitFilePath(const std::string& kind, const std::string& name);

// A folder `root`/NAME holding a copy of solutions/ with the exercise file
// `exerciseFile` ("05-ggx.glsl") replaced by `mutant` (a course mutant,
// course/<unit>/mutants/<name>.glsl); NAME is the file's unit and stem.
std::filesystem::path solutionsWithMutant(const std::filesystem::path& root, const std::string& exerciseFile,
                                          const std::filesystem::path& mutant);

// A wall lit by a light in front of it, a sphere behind the light (and behind
// the camera), 32x24: a shadow ray that does not stop at the light finds the
// sphere (04's "occluders beyond" mistake shows at the wall's centre).
extern const char* const kBeyondScene;

// Renders with OpenGL (solutions/, a headless context made once per process).
Rendering renderGl(const Scene& scene, const std::string& backend = "auto");

// "off 0.12% mean 0.03 p99 1 maxLsb 2 pfmRel 1e-6 nonFinite 0", for messages.
std::string describe(const ImageDiff& d);

}  // namespace rl::test
