#pragma once
// The define functions as they were before the table (render/define_table.h),
// kept only to compare the table's output with theirs (test_define_table.cpp).


#include <optional>

#include "core/scene.h"
#include "shader/shader_library.h"

namespace rl::old {

// RL_D_BECKMANN, RL_G_..., RL_F_..., RL_FD_BURLEY, RL_BLINN_PHONG; empty for
// the reference model (app/render/model_defines.cpp).
ShaderDefines modelDefines(const ShadingModel& model);

// Counts and the bounce limit as constants, features the scene does not use
// left out (app/render/specialisation.cpp).
ShaderDefines specialisationDefines(const Scene& scene);

// Of specialisationDefines(), only what the scene's structure decides
// (sphere and light counts, the bounce limit, what the model implies, which
// spheres are huge), nothing the live view's panel edits: what the live view
// compiles in, so a slider never recompiles and adding a sphere or a bounce
// may (specialisation.cpp).
ShaderDefines structuralDefines(const Scene& scene);

// Both together: what `raylab render` and the live view compile with.
ShaderDefines shaderDefinesFor(const Scene& scene, bool specialise);

// For a frame that shows the picture or a bounce view, known before the
// program is built: the teaching term views (d, g, f, ...) left out, and a
// traceRay whose helpers are started trusted without a per-ray fallback
// (app/render/specialisation.cpp). `raylab render` adds it to a specialised
// program; the live view, which switches views at a key press and shows
// half-written exercises, does not.
ShaderDefines pictureOnlyDefines();

// From the spheres' centres and radii alone (which the live view's panel does
// not edit), in double: RL_RESIDUAL_SPHERES, the spheres for which makeHit()
// can need its residual form (a huge sphere near the scene's anchor; none for
// more than 31 spheres). `raylab render` and the live view compile it in.
ShaderDefines residualSphereDefines(const Scene& scene);

// RL_SAMPLE_GRID: n for the scene's n x n samples per pixel, a constant.
// `raylab render` compiles it in; so does the live view, whose panel offers
// four sample counts (1, 4, 9, 16) and keeps a program per count, like the
// bounce limit.
ShaderDefines sampleGridDefines(const Scene& scene);

// For a program that renders pictures of this scene from this camera
// (`raylab render`): residualSphereDefines(), sampleGridDefines(), and
// RL_CAMERA_FROM_ANCHOR, the camera's position, which the live view's camera
// moves (app/render/specialisation.cpp).
ShaderDefines pictureValueDefines(const Scene& scene);

// RL_EXERCISES_FINISHED when every exercise file of `impl` is written and none
// of them names NOT_STARTED outside comments: no stub test can fire, and the
// shader drops them (stub_marker.glsl). Empty otherwise.
ShaderDefines finishedExerciseDefines(const Implementation& impl);

// What the files of `impl` allow, whatever the scene's values and camera
// (so the live view compiles it too, and recomputes it on a hot reload):
// finishedExerciseDefines(impl), and RL_SEGMENT_TEST when 02-intersect is
// the course's solution. Reads the files.
ShaderDefines fileDefines(const Implementation& impl);

// fileDefines() `files` with what they allow for the structure of `scene`:
// RL_CANDIDATE_SHADOWS from 12 spheres when every exercise is written, and
// RL_SELECT_LIGHTS (the direct light summed by selects) when every exercise
// is written and the shadow tests stay unrolled.
ShaderDefines implementationDefines(const Scene& scene, const ShaderDefines& files);

// Whether exercise 09 of `impl` is no longer the shipped stub: then a
// picture program may trust traceRay() and leave out the per-ray fallback
// to the first hit (render, the live view and its bench all ask this).
bool traceStarted(const Implementation& impl);

// What `raylab render` compiles for the picture (or a bounce view) of `scene`
// with `impl`: shaderDefinesFor(scene, true), and, unless exercise 09 is still
// the shipped stub (then the per-ray fallback to the first hit is kept),
// pictureOnlyDefines(), pictureValueDefines(scene) and
// implementationDefines(scene, fileDefines(impl)), and what this camera and
// the course's own files allow: RL_CAMERA_OUTSIDE (every hit seen from
// outside) and the shadow cones (RL_SHADOW_CONES, render/shadow_cones.h) with
// their candidate loop from two spheres on. The bench's "specialised" row and
// the accuracy tests compile the same.
ShaderDefines renderProgramDefines(const Scene& scene, const Implementation& impl);

// Not a GLSL define: set by renderProgramDefines() when the program's screen
// tiles that no camera ray can hit a sphere in may be drawn by the program of
// skyProgramDefines() (render/sky_tiles.h). The bench's layers sweep takes it
// out like any other.
inline constexpr const char* kSkyTilesDefine = "RL_SKY_TILES";

// The program for the sky tiles of a picture program: the same defines with no
// sphere (RL_SPHERE_COUNT 0), so that it draws what the picture program draws
// where every camera ray misses, by the same code. None unless `picture` has
// kSkyTilesDefine.
std::optional<ShaderDefines> skyProgramDefines(const ShaderDefines& picture);

}  // namespace rl::old
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


#include "render/scene_uniforms.h"


namespace rl::old {


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

}  // namespace rl::old
