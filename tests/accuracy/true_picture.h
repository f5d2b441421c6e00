// The true picture of a scene, as the issue #10 judge defines it: the model
// of reference-model.md in double precision with near-zero ray offsets. A
// sphere is convex, so a secondary ray needs none for the sphere it leaves
// (skipped from outside, its far root from inside); every other sphere is
// intersected from 2^-40 of the hit's magnitude off the exact surface point. Independent of the GLSL and of
// the CPU reference's offsets (only the BRDF terms of brdf_reference.h are
// shared). Until the CPU reference itself is offset-free, the hard cases
// judge the GLSL against this.
#pragma once

#include "core/image.h"
#include "core/scene.h"

namespace rl::acc {

Rendering renderTruePicture(const Scene& scene);

}  // namespace rl::acc
