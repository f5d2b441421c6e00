// raytracer.glsl: every module of the ray tracer, in the order they build on
// each other. main.frag (the picture) and probe.frag (the exercise checks)
// both start from here.
#include "common.glsl"
#include "scene.glsl"
#include "declarations.glsl"
#include "environment.glsl"  // light from all around: only with RL_ENVIRONMENT (a scene's "environment")
#include "error_bounds.glsl"
#include "shadow_segment.glsl"     // the exact shadow test of one sphere
#include "shadow_light_side.glsl"  // ... and from the light's side, in a program for one scene
#include "intersect_scene.glsl"
#include "loop_guard.glsl"
#include "exercises.glsl"  // written by the host: the exercise files, what is not ready replaced
#include "unfinished.glsl"
#ifdef RL_MODEL_VARIANTS  // a scene "model" other than the reference (app/render/define_table.cpp)
#include "model_variants.glsl"
#endif
#include "lighting.glsl"
#ifdef RL_PIXEL_DEBUG  // the pixel debugger's program (pixel_debug.frag)
#include "pixel_debug.glsl"
#endif
#include "trace.glsl"
#include "camera.glsl"
#include "display.glsl"
#include "views.glsl"
