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

// True when `file` is the stub shipped in exercises/ for this exercise,
// ignoring white space (what `raylab check` reports as NOT STARTED).
bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise);

}  // namespace rl
