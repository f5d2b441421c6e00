// Shadow cones: where, seen from a light, each sphere can stand in the way.
// A shadow ray runs from a point to light k; sphere j can block it only if
// the direction from the light to the point lies within the cone from the
// light around sphere j (half-angle asin(r / d), d the distance from the
// light to the centre) and the point is farther from the light than the
// sphere's nearest point (d - r). The host computes both per light and
// sphere, in double from the float32 values the shader holds, and a program
// for one picture compiles them in as constants (RL_SHADOW_CONES,
// shaders/intersect_scene.glsl): a dot product and two comparisons decide
// which spheres the exact test (segmentCrossesSphere) must still look at,
// where mayHitSphere() needs three dot products and a margin per ray.
// docs/performance.md, "Shadow cones", measures it.
#pragma once

#include "core/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace rl {

struct ShadowCone {
    glm::vec3 axis{0.0f};      // unit, from the light towards the centre (0 when always a candidate)
    float minCos = -2.0f;      // the ray's direction d passes when -dot(d, axis) >= minCos
    float nearest = 0.0f;      // ... and the ray's length tMax >= nearest
};

// One cone per light and sphere, light-major ([k * spheres + j]), in the
// shader's units relative to the scene's anchor (SceneUniformBlock::upload).
// Conservative: widened by 1e-5 of the farthest distance from the light to
// any sphere (float32's rounding of the exact test is below 1e-6 of it), the
// cosine lowered by 1e-6 (its own rounding is a few 1e-8), and a light inside
// a sphere, or at its surface, makes that sphere a candidate always.
std::vector<ShadowCone> shadowCones(const Scene& scene);


}  // namespace rl
