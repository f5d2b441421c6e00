// The offset-free oracle of the metamorphic suite: the reference model
// rendered with no ray offset at all, its geometry (ray/sphere roots, hit
// points, normals, reflections, shadow rays) in long double (x87, 64-bit
// mantissa: 2^11 times finer than double) and the sphere a secondary ray
// leaves handled exactly (skipped from outside, its far root from inside).
// It is what the spec calls the geometric truth; the CPU reference
// (app/reference/cpu_reference.cpp, double, reprojected hits, rounding-sized
// offsets) is judged against it. The shading terms are the reference's own
// (brdf_reference.h, double): they do not decide where a ray goes.
#pragma once

#include "core/image.h"
#include "core/scene.h"

namespace rl::meta {

// The picture of `scene` (linear radiance and 8-bit display), as renderCpu
// lays it out. Rows are shared among `threads` threads (0: all cores).
Rendering renderOracle(const Scene& scene, int threads = 0);

}  // namespace rl::meta
