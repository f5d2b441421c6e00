#include "core/paths.h"

#include "root_directory.h"

#include <cstdlib>

namespace rl {

std::filesystem::path sourceRoot() {
    if (const char* root = std::getenv("RAYLAB_ROOT"); root && *root) return root;
    return RAYLAB_SOURCE_ROOT;
}

std::filesystem::path shadersDir() { return sourceRoot() / "shaders"; }
std::filesystem::path solutionsDir() { return sourceRoot() / "solutions"; }
std::filesystem::path exercisesDir() { return sourceRoot() / "exercises"; }
std::filesystem::path courseDir() { return sourceRoot() / "course"; }
std::filesystem::path scenesDir() { return sourceRoot() / "scenes"; }

bool hasSolutions() {
    std::error_code ec;
    return std::filesystem::is_directory(solutionsDir(), ec);
}

std::filesystem::path defaultImplementationDir() { return hasSolutions() ? solutionsDir() : exercisesDir(); }

}  // namespace rl
