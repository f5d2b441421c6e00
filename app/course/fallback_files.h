// Where an exercise file comes from when the folder in use does not have it.
// In the instructor's repository: solutions/. In a student edition
// (scripts/student-edition.sh), which has no solutions/: the shipped stubs as
// compiled into the program, so a picture shows the stub's stripes where a
// file is missing and never borrows an answer (docs/decisions.md, "A student
// edition").
#pragma once


#include <filesystem>

namespace rl {

// The shipped stubs (shippedStub()) written once per process to a private
// temporary folder, removed at exit. A stub that was not compiled in (the
// file was edited before the first build) is absent from it.
const std::filesystem::path& shippedStubFolder();

// solutions/ where the repository has it, else shippedStubFolder().
std::filesystem::path fallbackImplementationDir();

}  // namespace rl
