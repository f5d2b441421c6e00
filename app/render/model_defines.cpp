#include "render/shader_config.h"

namespace rl {

ShaderDefines modelDefines(const ShadingModel&) { return {}; }  // variants: not yet in GLSL

}  // namespace rl
