// The bench's straightforward yardstick: shaders/yardstick/textbook.frag,
// the model written the plain way with none of raylab's layers. The
// strongest yardstick, which every speed ratio is against, is the expert
// one (bench/expert.h); this one stays beside it.
#pragma once

#include "core/scene.h"
#include "shader/program.h"

#include <string>

namespace rl::bench {

// Why the textbook cannot be drawn ("" when it can): a student edition
// (scripts/student-edition.sh) leaves shaders/yardstick/textbook.frag out,
// since it writes every formula of the model the plain way.
std::string textbookUnsupported();

// Compiles the textbook program (throws ShaderError / rl::Error like any program).
ShaderProgram buildTextbook();

// Its tb_ uniforms for `scene` (camera frame in double, then float32). They
// live in the program object: set them once after building, before drawing.
void setTextbookUniforms(const ShaderProgram& program, const Scene& scene);

}  // namespace rl::bench
