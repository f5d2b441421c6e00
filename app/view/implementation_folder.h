// What `--impl` and `--compare` name: exercise files.
//  * A folder with all ten (exercises/, solutions/, a student's copy) is used
//    as it is.
//  * A folder with only some of them (one exercise a student is working on)
//    takes the others from solutions/, the way a check puts one student file
//    beside the solutions; in a student edition, which has no solutions/,
//    from the shipped stubs (course/fallback_files.h).
//  * A single file named EXERCISE--WHAT.glsl, as tests/mutants/ names them
//    ("05-ggx--missing-pi.glsl"), or EXERCISE.glsl, replaces that exercise of
//    solutions/ (of the shipped stubs in a student edition).
#pragma once

#include "shader/shader_library.h"

#include <filesystem>
#include <string>

namespace rl {

// Throws rl::Error "--impl: PATH does not exist" / "... has none of the
// exercise files (01-camera.glsl ... 10-display.glsl)" / "... is not named
// after an exercise". `option` names the flag in messages.
Implementation implementationFrom(const std::filesystem::path& path, const std::string& option);

// A short name for labels on screen: "exercises", "mutants/05-ggx--missing-pi.glsl (+ solutions)",
// "mine/05-ggx.glsl (+ shipped stubs)".
std::string implementationLabel(const Implementation& impl);

}  // namespace rl
