// Exercise 12's model in double precision (reference.cpp).
#pragma once

#include <glm/vec3.hpp>

namespace rl::ref {

// The form factor of the sphere (centre, radius) seen from p with unit
// normal n: the share of the cosine-weighted hemisphere around n that the
// sphere covers (docs/model.md, "Occlusion by the spheres"). p outside it.
double sphereFormFactor(glm::dvec3 p, glm::dvec3 n, glm::dvec3 centre, double radius);

// The same from h = d / radius > 1 and cos(beta) = n . w.
double sphereFormFactor(double h, double cosBeta);

}  // namespace rl::ref
