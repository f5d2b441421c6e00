// What the defines of a program need to know about an implementation's files
// (render/define_table.h), read from the files once: when a program is
// built (`raylab render`, the bench, the checker) or a file changes (the
// live view's hot reload). definesFor() itself then reads no file.
//
// A fact of a new kind (an exercise started, a framework path ready) is a
// field here, set in implementationFacts(), and the rows that read it.
#pragma once

#include "shader/shader_library.h"

#include <set>
#include <string>

namespace rl {

struct ImplementationFacts {
    // Every exercise file is written and none names NOT_STARTED outside
    // comments: no stub test can fire (RL_EXERCISES_FINISHED).
    bool exercisesFinished = false;
    // Exercise 09 is no longer the shipped stub: a picture program may trust
    // traceRay() and leave out the per-ray fallback to the first hit.
    bool traceStarted = false;
    // The exercise files ("02-intersect.glsl") whose text is the course's
    // solution, white space aside (the checker's program trusts the course's
    // own 09 to have started every ray: define_table.cpp, RL_PICTURE_ONLY).
    std::set<std::string> courseFiles;

    bool courseFile(const std::string& file) const { return courseFiles.count(file) != 0; }
};

// Reads the exercise files of `impl` (and the course's solutions to compare
// with). An unreadable file counts as unfinished and not the course's: the
// compiler says why when the program is built.
ImplementationFacts implementationFacts(const Implementation& impl);

}  // namespace rl
