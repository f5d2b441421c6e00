// The ten exercises: their files, titles and handouts. The order is the
// teaching order; each builds on the ones before it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

struct ExerciseInfo {
    int number;          // 1..10
    std::string id;      // "05-ggx": file stem in exercises/ and solutions/
    std::string title;   // "the GGX normal distribution D"
    std::string file() const { return id + ".glsl"; }
    std::string handout() const { return "docs/exercises/" + id + ".md"; }
};

const std::vector<ExerciseInfo>& allExercises();
// By number (1..10) or id ("05-ggx"); throws rl::Error listing the valid ones.
const ExerciseInfo& findExercise(const std::string& numberOrId);

// True when `file` is the stub shipped for this exercise (what `raylab check`
// reports as NOT STARTED): the same text once white space (CR included) and a
// UTF-8 byte-order mark are dropped. "Shipped" is exercises/ as it was when the
// program was built (compiled in, see cmake/shipped_stubs.cmake), never the
// live folder, which is the student's own work.
bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise);

// The comparison form of GLSL text: no white space, no BOM.
std::string normalisedGlsl(const std::string& text);

// The shipped stub `fileName` ("05-ggx.glsl") as compiled in, or nullptr.
// Defined in the generated shipped_stubs.cpp.
const std::string* shippedStub(const std::string& fileName);

}  // namespace rl
