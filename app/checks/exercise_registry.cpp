#include "checks/exercise_registry.h"

#include "core/error.h"
#include "core/message.h"
#include "core/paths.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace rl {

const std::vector<ExerciseInfo>& allExercises() {
    static const std::vector<ExerciseInfo> list = {
        {1, "01-camera", "camera rays through pixel centres and sub-samples"},
        {2, "02-intersect", "ray/sphere intersection, numerically stable"},
        {3, "03-lambert", "Lambert diffuse under a point light"},
        {4, "04-shadows", "shadow rays with a scale-aware offset"},
        {5, "05-ggx", "the GGX normal distribution D"},
        {6, "06-geometry", "the Smith / Schlick-GGX geometry term G"},
        {7, "07-fresnel", "Schlick's Fresnel F"},
        {8, "08-cook-torrance", "Cook-Torrance assembly, metallic workflow"},
        {9, "09-reflections", "Fresnel-attenuated reflection bounces"},
        {10, "10-display", "exposure, tone mapping and gamma"},
    };
    return list;
}

const ExerciseInfo& findExercise(const std::string& key) {
    for (const ExerciseInfo& e : allExercises()) {
        if (key == e.id || key == e.file() || key == std::to_string(e.number) ||
            (key.size() == 2 && key[0] == '0' && key.substr(1) == std::to_string(e.number)))
            return e;
    }
    std::string valid;
    for (const ExerciseInfo& e : allExercises()) valid += (valid.empty() ? "" : ", ") + std::to_string(e.number);
    throw Error("--exercise: no exercise " + quotedValue(key) + " (expected one of " + valid + ", or a name like 05-ggx)");
}

namespace {

std::string withoutSpaces(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::string out;
    for (char c : text.str())
        if (!std::isspace(static_cast<unsigned char>(c))) out += c;
    return out;
}

}  // namespace

bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise) {
    std::error_code ec;
    constexpr std::uintmax_t kLargerThanAnyStub = 1 << 20;  // a bigger file is no stub; don't read it
    if (!std::filesystem::is_regular_file(file, ec) || std::filesystem::file_size(file, ec) > kLargerThanAnyStub)
        return false;
    return withoutSpaces(file) == withoutSpaces(exercisesDir() / exercise.file());
}

}  // namespace rl
