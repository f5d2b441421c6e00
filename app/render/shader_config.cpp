#include "render/shader_config.h"

namespace rl {

ShaderDefines shaderDefinesFor(const Scene& scene, bool specialise) {
    ShaderDefines defines = modelDefines(scene.model);
    if (specialise)
        for (const auto& [name, value] : specialisationDefines(scene)) defines[name] = value;
    return defines;
}

}  // namespace rl
