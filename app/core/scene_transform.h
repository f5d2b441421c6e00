// Whole-scene transforms used by the checks and the hard numerical cases:
// the same picture at another scale or place.
#pragma once

#include "core/scene.h"

namespace rl {

// Positions and radii times s, light intensities times s^2 (so irradiance,
// which falls with the square of distance, is unchanged).
Scene scaledScene(const Scene& scene, double s);
// Every position (camera, target, lights, centres) moved by `offset`.
Scene translatedScene(const Scene& scene, const glm::dvec3& offset);

}  // namespace rl
