// The defines that select the model variants of shaders/model_variants.glsl
// (docs/model-variants.md). The reference model gets none, so its shader is
// the one it always was and every reference scene shares one program.
#include "render/shader_config.h"

namespace rl {

ShaderDefines modelDefines(const ShadingModel& model) {
    ShaderDefines defines;
    if (model.isReference()) return defines;
    defines["RL_MODEL_VARIANTS"] = "1";  // raytracer.glsl includes model_variants.glsl
    if (model.blinnPhong) {
        // The whole BRDF is replaced and the other switches are ignored (as in
        // the CPU reference), so they add no define: scenes that differ only
        // in ignored switches share one program.
        defines["RL_BLINN_PHONG"] = "1";
        return defines;
    }
    switch (model.distribution) {
        case DistributionModel::GGX: break;
        case DistributionModel::Beckmann: defines["RL_D_BECKMANN"] = "1"; break;
    }
    switch (model.geometry) {
        case GeometryModel::SchlickGGX: break;
        case GeometryModel::SmithGGXSeparable: defines["RL_G_SMITH_SEPARABLE"] = "1"; break;
        case GeometryModel::SmithGGXCorrelated: defines["RL_G_SMITH_CORRELATED"] = "1"; break;
    }
    switch (model.fresnel) {
        case FresnelModel::Schlick: break;
        case FresnelModel::Dielectric: defines["RL_F_DIELECTRIC"] = "1"; break;
        case FresnelModel::Conductor: defines["RL_F_CONDUCTOR"] = "1"; break;
    }
    switch (model.diffuse) {
        case DiffuseModel::Lambert: break;
        case DiffuseModel::Burley: defines["RL_FD_BURLEY"] = "1"; break;
    }
    return defines;
}

}  // namespace rl
