// Which side of a sphere's surface a light lies on (docs/model.md, "A light
// on a surface"). A light on the surface is hidden by neither side of it:
// every renderer (the GLSL, the CPU reference, the metamorphic suite's
// oracle) decides that case by this one function instead of by a ray's root
// at the light's distance, which rounds either way pixel by pixel.
#pragma once

#include "core/scene.h"

namespace rl {

// -1 inside, 0 on, +1 outside `sphere`. "On" means within
// kLightOnSurfaceUlps roundoffs of double of the numbers that place the two
// (|light| + |centre| + radius, largest components): closer than the scene
// file's decimal numbers can place a light on a surface (a light written at
// (0, 0.9, 0) on a sphere of centre (0, 0.2, 0) and radius 0.7 is 5.6e-17
// off it in binary).
int lightSurfaceSide(const glm::dvec3& light, const Sphere& sphere);

// 2^6 roundoffs of double, 2^-46 = 1.4e-14 relative: a few roundings of the
// scene's numbers (the file's decimals, a transform) with room to spare.
constexpr double kLightOnSurfaceTolerance = 1.4210854715202004e-14;

// The signed distance |point - centre| - r.
double surfaceDistance(const glm::dvec3& point, const Sphere& sphere);

}  // namespace rl
