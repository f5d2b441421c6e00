// The form factor of a sphere in double: the model of exercise 12
// (course/12-sky-shadows) and of the environment's occlusion (docs/model.md,
// "Occlusion by the spheres"), for its probes and the pixel debugger.
#pragma once

#include "core/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace rl::ref {

// The form factor of the sphere (centre, radius) seen from p with unit
// normal n: the share of the cosine-weighted hemisphere around n that the
// sphere covers (docs/model.md, "Occlusion by the spheres"). p outside it.
double sphereFormFactor(glm::dvec3 p, glm::dvec3 n, glm::dvec3 centre, double radius);

// The same from h = d / radius > 1 and cos(beta) = n . w.
double sphereFormFactor(double h, double cosBeta);

// The form factors of every sphere but `own` seen from p, summed (a sphere p
// lies inside of counts 1): what the pixel debugger compares with the
// student's sphereFormFactor() at a hit.
double summedFormFactors(const std::vector<Sphere>& spheres, int own, glm::dvec3 p, glm::dvec3 n);

}  // namespace rl::ref
