// Which #defines the ray tracer is compiled with for a scene: the model
// variants it uses (compiled in only then) and, when specialised, the
// scene's structure as constants. Two scenes with equal defines share one
// compiled program; the live view recompiles only when they differ.
#pragma once

#include "core/scene.h"
#include "shader/shader_library.h"

namespace rl {

// RL_D_BECKMANN, RL_G_..., RL_F_..., RL_FD_BURLEY, RL_BLINN_PHONG; empty for
// the reference model (app/render/model_defines.cpp).
ShaderDefines modelDefines(const ShadingModel& model);

// Counts and the bounce limit as constants, features the scene does not use
// left out (app/render/specialisation.cpp).
ShaderDefines specialisationDefines(const Scene& scene);

// Both together: what `raylab render` and the live view compile with.
ShaderDefines shaderDefinesFor(const Scene& scene, bool specialise);

}  // namespace rl
