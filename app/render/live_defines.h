// The programs of the live view (`raylab view`), specialised to the scene's
// structure while every value stays a uniform: a slider never recompiles;
// adding a sphere or a light, changing the bounce limit or the model does
// (structuralDefines(), render/shader_config.h).
//
// Two programs per implementation, each built when first needed and kept
// (view/live_program.h), chosen by what `raylab bench --sweeps view` measured
// on llvmpipe (docs/performance.md, "The live view"):
//   picture  the picture and the bounce views: modelDefines(), the scene's
//            structure (structuralDefines()), which spheres may need
//            makeHit()'s residual form (residualSphereDefines(): from the
//            geometry alone), pictureOnlyDefines() and what the files allow
//            (implementationDefines()), as `raylab render` draws it less what
//            depends on values or the camera (RL_NO_METALS, RL_SAMPLE_GRID,
//            RL_CAMERA_FROM_ANCHOR)
//   views    the teaching term views (D, G, F, n.l, ...): the generic program
//            (modelDefines() only). With the term views compiled in, the
//            structure's unrolled loops made it slower, not faster (0.56x
//            to 0.67x of the generic one at 1280x720), and its first draw
//            (llvmpipe's JIT) 4x longer.
// Until exercise 09 is started, every view uses the generic program: its
// per-ray fallback to the first hit is what the picture program leaves out.
#pragma once

#include "render/scene_uniforms.h"
#include "render/shader_config.h"

namespace rl {

// True for the views the picture program draws (final, bounce K).
bool isPictureView(View view);

// The defines of the live program for `view`. `model`: the model this side
// shows (--compare-model), usually scene.model. `traceStarted`: exercise 09
// is no longer the shipped stub (then the picture program may trust it, as
// `raylab render` does); false keeps the first-hit fallback of the full
// program for every view. `files`: fileDefines() of the side's files at
// its last (re)build (no stub tests when every exercise is written, the
// course's 02 as a segment test), with what they allow for the scene's
// structure (implementationDefines()).
ShaderDefines liveViewDefines(const Scene& scene, const ShadingModel& model, View view, bool traceStarted,
                              const ShaderDefines& files = {});

}  // namespace rl
