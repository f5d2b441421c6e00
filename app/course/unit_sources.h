// The course's units as compiled in by the build (cmake/course.cmake writes
// the generated course_units.cpp from course/*/unit.json and stub.glsl): the
// raw text the registry (exercise_registry.cpp) reads. Nothing else uses it.
#pragma once

#include <string>
#include <vector>

namespace rl {

struct UnitSource {
    const char* id;        // "05-ggx": the unit's folder in course/
    int position;          // its line among the manifest's units (0, 1, ...), or -1: not in the course
    const char* json;      // unit.json
    const char* stub;      // stub.glsl
    bool optional;         // the manifest's line says "optional" (a bonus exercise)
};

// Every unit, the course's first (in the manifest's order), then the others.
const std::vector<UnitSource>& unitSources();

}  // namespace rl
