// The bench's strongest yardstick, `expert`: a hand-optimised GLSL shader
// for the model of docs/model.md, written out per scene by a generator (the
// way an expert would hand-write it for that scene, with no framework
// constraints and no per-scene tuning: every choice below is made by a rule
// from the scene's numbers). Every speed ratio `raylab bench` prints and
// docs/performance.md quotes is against it, measured in the same run; the
// straightforward yardstick (bench/textbook.h) stays beside it.
//
// Techniques (issue #25): scene data and loops as constants, per-sphere
// tables of few values as selects (never an array indexed per pixel where
// it can be helped); the camera basis folded into one pixel-to-direction
// expression; camera-relative centres and per-sphere |oc|^2 - R^2 in double
// on the host; the near root as one expression when the camera is outside;
// branch-free nearest hit; no ray offsets (a ray never re-tests the sphere it
// leaves from outside; from inside the far root is 2R(n.d)); shadow tests
// from the light's side with per-(light, sphere) constants and no square
// root, branch-free (llvmpipe runs an `if` body for the whole 8-pixel group
// anyway), only for the spheres some (light, receiver) pair lets block;
// lights behind the surface skipped before any shadow work; h never
// normalised; n.l and n.v cancelled out of G/(4 n.l n.v); x^5 by
// multiplications; no work after the last bounce.
#pragma once

#include "core/scene.h"
#include "shader/program.h"

#include <string>

namespace rl::bench {

// Why the expert cannot render `scene` ("" when it can): it writes the
// reference model only (no model variants).
std::string expertUnsupported(const Scene& scene);

// The fragment shader's text for `scene` at scene.render's size (GLSL 3.30,
// every number a constant: no uniforms).
std::string expertFragmentSource(const Scene& scene);

// Compiles it with fullscreen.vert (throws ShaderError / rl::Error).
ShaderProgram buildExpert(const Scene& scene);

}  // namespace rl::bench
