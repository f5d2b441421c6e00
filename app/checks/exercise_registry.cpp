#include "checks/exercise_registry.h"

#include "core/error.h"
#include "core/message.h"

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

std::string normalisedGlsl(const std::string& text) {
    // A UTF-8 byte-order mark (some Windows editors write one) and white space
    // (CR included) do not count. Comments do: a file with a comment added is
    // judged by its probes, which still find every function NOT_STARTED.
    std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    std::string out;
    for (std::size_t i = start; i < text.size(); ++i)
        if (!std::isspace(static_cast<unsigned char>(text[i]))) out += text[i];
    return out;
}

bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise) {
    const std::string* stub = shippedStub(exercise.file());
    std::error_code ec;
    constexpr std::uintmax_t kLargerThanAnyStub = 1 << 20;  // a bigger file is no stub; don't read it
    if (!stub || !std::filesystem::is_regular_file(file, ec) ||
        std::filesystem::file_size(file, ec) > kLargerThanAnyStub)
        return false;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return normalisedGlsl(text.str()) == normalisedGlsl(*stub);
}

}  // namespace rl
