#include "render/live_defines.h"

namespace rl {

bool isPictureView(View view) { return view == View::Final || view == View::Bounce; }

ShaderDefines liveViewDefines(const Scene& scene, const ShadingModel& model, View view, bool traceStarted,
                             const ShaderDefines& files) {
    ShaderDefines defines = modelDefines(model);
    if (!traceStarted || !isPictureView(view)) return defines;  // the generic program (live_defines.h says why)
    for (const ShaderDefines& more : {structuralDefines(scene), residualSphereDefines(scene), sampleGridDefines(scene),
                                       pictureOnlyDefines(), implementationDefines(scene, files)})
        for (const auto& [name, value] : more) defines[name] = value;
    return defines;
}

}  // namespace rl
