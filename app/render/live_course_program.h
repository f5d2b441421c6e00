// The live view's picture program for the course's own exercise files
// (issue #25): the course generator's structure (render/course_program.h:
// loops written out per sphere and light, the camera as one
// pixel-to-direction expression, no ray offsets, branch-free nearest hit,
// shadow tests from the light's side with no square root, h never
// normalised, ...) with every value a uniform: materials, light positions,
// colours and intensities, sphere centres and radii, the camera, exposure,
// background and gamma. A slider or a camera drag then sets uniforms only.
//
// The source is a function of the scene's structure alone (liveCourseSource()):
// the counts, the bounce limit, samples per pixel, tone map and sRGB, and
// a few classes the host decides in double for the current camera (per
// sphere: camera far outside, near the surface or inside; per light and
// sphere: the light outside or inside; whether any two spheres overlap;
// which spheres are huge). The caller compares it with the source of the
// program it holds: equal, set the values and draw; different, the
// structure changed (docs/decisions.md, "The live view's generated
// program": during a drag the view draws with its uniforms-only program and
// compiles the new structure when the hand stops).
//
// A student's own file is never replaced: liveCourseApplies() is false and
// the view runs that file's code.
#pragma once

#include "core/scene.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "render/scene_uniforms.h"
#include "shader/program.h"

#include <string>

namespace rl {

// Whether the view may draw `scene` with the generated program: the course's
// own files and the reference model (courseProgramApplies()), and few
// enough spheres and lights for its uniforms.
bool liveCourseApplies(const Scene& scene, const ImplementationFacts& facts);

// The fragment shader for `scene` seen from `frame`'s camera (GLSL 3.30,
// without the prelude): depends on the structure only, never on a value.
std::string liveCourseSource(const Scene& scene, const FrameSettings& frame);

// Compiles `source` (from liveCourseSource()) with fullscreen.vert.
ShaderProgram buildLiveCourseProgram(const std::string& source);
// The same with, where the scene has a sphere, the same generator's program
// with no sphere for the tiles no camera ray can hit one in (render/sky_tiles.h,
// GlRenderer::draw(const PictureProgram&, ...)); it reads only the plain
// uniforms GlRenderer sets (background, exposure, gamma).
PictureProgram buildLiveCoursePicture(const Scene& scene, const std::string& source);

// Sets every value uniform of a program built from
// liveCourseSource(scene, frame) (the plain uniforms of setFrameUniforms()
// that it reads are set by GlRenderer::draw()). Leaves the program in use.
void setLiveCourseValues(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame);

}  // namespace rl
