// Yardsticks from outside: `raylab bench --yardstick FILE` times a fragment
// shader somebody else wrote beside raylab's programs, in the same run, the
// same harness and the same frame (640x480 targets, the same clock, the same
// copies rule), and compares its picture with the same CPU reference. It then
// competes for "the strongest yardstick" that every ratio is against
// (docs/performance.md, "Bring your own yardstick"), so that nobody has to
// take the team's own yardsticks on trust.
//
// The contract (docs/performance.md): GLSL 3.30 (a file without a #version
// line gets `#version 330 core`); `gl_FragCoord.xy` is the pixel, (0.5, 0.5)
// at the bottom left, on a target of the scene's size; write the display
// value (after tone mapping, in [0, 1]) to `layout(location = 0) out vec4`,
// and the radiance to location 1 if you like (the bench's error is measured
// on the display bytes). The scene's numbers may be written into the shader,
// or read from the uniforms the textbook yardstick gets (tb_eye, tb_right,
// tb_up, tb_forward, tb_resolution, tb_center[], tb_radius[], ...:
// shaders/yardstick/textbook.frag), which are set when the shader has them.
#pragma once

#include "core/scene.h"
#include "shader/program.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rl::bench {

// The most a yardstick file may hold: a shader, not a data file.
constexpr std::uintmax_t kOutsideShaderMaxBytes = std::uintmax_t(1) << 20;

// The bench's row name for FILE: "outside:" and the file's stem.
std::string outsideVariantName(const std::filesystem::path& file);

// Reads FILE (at most kOutsideShaderMaxBytes) and compiles it with fullscreen.vert; a compile
// error names FILE and its line (ShaderError), an unreadable file is an
// rl::Error naming it. The tb_ uniforms of `scene` are set on the program.
ShaderProgram buildOutside(const std::filesystem::path& file, const Scene& scene);

}  // namespace rl::bench
