// The values of the scene-derived rows of the define table
// (render/define_table.h): each a pure function of the scene, in double
// where it decides from geometry. Why each pays: the table's reason column
// and docs/performance.md.
//
// Why constants pay on llvmpipe: a loop over a uniform count reads the
// uniform block with a per-lane gather in every iteration, and a constant
// count unrolls into direct loads; a feature left out costs nothing, while
// a feature behind a uniform branch costs its full price on a CPU rasteriser,
// which runs both sides of every branch under a mask.
#pragma once

#include "core/scene.h"

#include <optional>
#include <string>

namespace rl {

// RL_REFINE_SPHERES: the mask of the spheres whose roots closestHit()
// refines (core/float_range.h refinesRoots()); none when one of them is
// sphere 31 or later (the mask is one int).
std::optional<std::string> refineSphereMask(const Scene& scene);

// RL_RESIDUAL_SPHERES: the mask of the spheres for which makeHit() can need
// its residual form (a huge sphere near the scene's anchor), from the
// centres and radii alone; none for 0 or more than 31 spheres.
std::optional<std::string> residualSphereMask(const Scene& scene);

// RL_SAMPLE_GRID: n for the scene's n x n samples per pixel.
std::string sampleGrid(const Scene& scene);

// RL_CAMERA_FROM_ANCHOR: the camera's position relative to the anchor, the
// float32 value the scene block holds, as a GLSL vec3 literal.
std::string cameraFromAnchor(const Scene& scene);

// RL_CAMERA_RIGHT, RL_CAMERA_UP, RL_CAMERA_BACK: column 0, 1 or 2 of the
// camera basis the shader gets (shaderCameraBasis(), render/scene_uniforms.h),
// from the scene's camera and size, as a GLSL vec3 literal.
std::string cameraBasisColumn(const Scene& scene, int column);

// RL_FOR_EACH_LIGHT(X) and RL_FOR_EACH_SPHERE(X): " X(0) X(1) ...", so that
// every index into the constant arrays is a constant (indexed by a variable,
// a constant array is copied into every pixel's memory: 20 times slower on
// llvmpipe).
std::string forEachIndex(std::size_t count);

}  // namespace rl
