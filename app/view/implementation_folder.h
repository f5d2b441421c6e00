// What `--impl DIR` and `--compare DIR` name: a folder with exercise files.
// A folder with all ten (exercises/, solutions/, a student's copy) is used
// as it is; a folder with only some of them (a mutant, one exercise a
// student is working on) takes the others from solutions/, the way a check
// puts one student file beside the solutions.
#pragma once

#include "shader/shader_library.h"

#include <filesystem>
#include <string>

namespace rl {

// Throws rl::Error "--impl: DIR is not a directory" / "... has none of the
// exercise files (01-camera.glsl ... 10-display.glsl)". `option` names the
// flag in messages.
Implementation implementationFromFolder(const std::filesystem::path& dir, const std::string& option);

// A short name for labels on screen: "exercises", "mutants/ggx-no-square (+ solutions)".
std::string implementationLabel(const Implementation& impl);

}  // namespace rl
