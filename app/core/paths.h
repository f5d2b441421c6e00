// Where raylab finds its own files. The source tree is used in place (no
// copies in bin/); RAYLAB_ROOT overrides it, e.g. for an installed copy.
#pragma once

#include <filesystem>

namespace rl {

std::filesystem::path sourceRoot();     // $RAYLAB_ROOT, else the configured source directory
std::filesystem::path shadersDir();     // <root>/shaders: the framework
std::filesystem::path solutionsDir();   // <root>/solutions
std::filesystem::path exercisesDir();   // <root>/exercises: the stubs as shipped
std::filesystem::path courseDir();       // <root>/course: the units (course/README.md)
std::filesystem::path scenesDir();      // <root>/scenes

// Whether <root>/solutions is a folder: the instructor's repository has it, a
// student edition (scripts/student-edition.sh) does not.
bool hasSolutions();
// What render, view, record and bench run without --impl: solutions/ where
// the repository has it, else exercises/ (the student's own files).
std::filesystem::path defaultImplementationDir();

}  // namespace rl
