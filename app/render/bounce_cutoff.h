// When a specialised shader may stop following mirror bounces: the host
// bounds what the rest of a path can still bring back (from the scene's
// lights, materials, ambient and background) and hands the bound, with the
// display step's parameters, to the shader as u_bounceCutoff
// (shaders/trace.glsl, bounceCannotChangeOutput). docs/performance.md derives
// the test; tests/bench/test_specialisation.cpp checks each part of it.
#pragma once

#include "core/scene.h"

#include <glm/vec4.hpp>

namespace rl {

// The brightest linear radiance (any channel) one hit can send in any
// direction: ambient * albedo * ao plus, for every light, C I / d^2 times the
// peak of f(l, v) NoL for the sphere's material, d the shortest distance from
// the light to the sphere's surface. Reference model only (the variants have
// other peaks): +infinity for any other model, and where a light touches a sphere.
double hitRadianceBound(const Scene& scene);

// The largest factor one bounce's Fresnel can apply to the throughput (any
// channel): max over spheres of max(1 - r, F0), r clamped to [kMinRoughness, 1] (reference/brdf_reference.h).
double bounceFresnelBound(const Scene& scene);

// The brightest linear radiance (any channel) a ray can bring back when it
// may hit at most `hits` surfaces (the last one without a reflection):
//     R(0) = 0,  R(k) = max(background, H + Fmax R(k - 1)).
// +infinity when H is.
double rayRadianceBound(const Scene& scene, int hits);

// The display step's tolerance the shader stops within (BOUNCE_CUTOFF_TOLERANCE
// in shaders/trace.glsl): a quarter of an 8-bit step.
constexpr double kBounceCutoffTolerance = 1.0 / 1024.0;

// u_bounceCutoff for the scene: x = 1 / (exposure R(maxBounces)) (0 when R is
// unbounded or gamma < 1, where the display step is not concave: then only a
// zero throughput stops), y = exposure / spp, z = 1 / gamma (0 for sRGB),
// w = the tone map.
glm::vec4 bounceCutoffUniform(const Scene& scene);

// The display step's slope dg/dc at exposed radiance c >= 0 for the scene's
// tone map and gamma: the C++ twin of displaySlope() in shaders/trace.glsl,
// for the tests.
double displaySlope(const RenderSettings& render, double c);

}  // namespace rl
