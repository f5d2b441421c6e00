#include "checks/exercise_registry.h"

#include "core/error.h"

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
    throw Error("--exercise: no exercise '" + key + "' (expected one of " + valid + ", or a name like 05-ggx)");
}

}  // namespace rl
