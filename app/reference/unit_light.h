// The extension point of the reference for a unit's further light term
// (course/README.md, "light"): what the unit's reference.cpp computes in
// double at a hit, added by shadeHit() to direct light and ambient, as
// lighting.glsl adds the unit's GLSL term. The build lists the terms
// (cmake/course.cmake writes course_references.cpp).
#pragma once

#include "core/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace rl::ref {

struct UnitLightInputs {
    glm::dvec3 p;        // the hit point
    glm::dvec3 n;        // its unit normal, facing the side the ray came from
    glm::dvec3 v;        // unit vector towards the viewer
    Material material;   // the sphere's
    const Scene* scene;  // the whole scene
};

using UnitLightFunction = glm::dvec3 (*)(const UnitLightInputs&);

struct UnitLightTerm {
    const char* unit;  // "11-hemisphere"
    UnitLightFunction radiance;  // linear radiance towards v
};

// Every unit's term (units without "light" have none).
const std::vector<UnitLightTerm>& unitLightTerms();

}  // namespace rl::ref

// The head of a unit's reference light term, in its reference.cpp, inside
// namespace rl::ref: RL_UNIT_LIGHT_REFERENCE(at) { return ...; }
#define RL_UNIT_LIGHT_CAT2(a, b) a##b
#define RL_UNIT_LIGHT_CAT(a, b) RL_UNIT_LIGHT_CAT2(a, b)
#define RL_UNIT_LIGHT_REFERENCE(at) glm::dvec3 RL_UNIT_LIGHT_CAT(unitLight_, RL_UNIT_SYMBOL)(const UnitLightInputs& at)
