#include "render/shader_config.h"

namespace rl {

ShaderDefines specialisationDefines(const Scene&) { return {}; }  // not yet specialised

}  // namespace rl
