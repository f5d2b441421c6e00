#include "course/exercise_registry.h"

#include "core/error.h"
#include "core/message.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace rl {

const std::vector<ExerciseInfo>& allExercises() {
    // The neutral values are what the picture showed before each exercise
    // existed: straight-ahead rays through pixel centres, nothing hit, no
    // direct light, no shadow, Lambert alone, the first hit only, a clamp for
    // the display step. The D, G and F views show black while their term is
    // not ready (every neutral term is 0).
    static const std::vector<ExerciseInfo> list = {
        {1, "01-camera", "camera rays through pixel centres and sub-samples",
         {{"sampleOffset", "return vec2(0.5);", {}},
          {"cameraRayDirection", "return normalize(forward);", {}, true}}},
        {2, "02-intersect", "ray/sphere intersection, numerically stable",
         {{"intersectSphere", "return NO_HIT;", {}, true}}},
        {3, "03-lambert", "Lambert diffuse under a point light",
         {{"Fd_Lambert", "return vec3(0.0);", {}},
          {"pointLightIrradiance", "return vec3(0.0);", {}}}},
        {4, "04-shadows", "shadow rays with a scale-aware offset",
         {{"offsetRayOrigin", "return p;", {}},
          {"lightVisibility", "return 1.0;", {"offsetRayOrigin"}}}},
        {5, "05-ggx", "the GGX normal distribution D", {{"D_GGX", "return 0.0;", {}}}},
        {6, "06-geometry", "the Smith / Schlick-GGX geometry term G",
         {{"G1_SchlickGGX", "return 0.0;", {}},
          {"G_SchlickGGX", "return 0.0;", {"G1_SchlickGGX"}}}},
        {7, "07-fresnel", "Schlick's Fresnel F", {{"F_Schlick", "return vec3(0.0);", {}}}},
        {8, "08-cook-torrance", "Cook-Torrance assembly, metallic workflow",
         {{"ggxAlpha", "return 1.0;", {}},  // the D view of a finished 05 shows the roughest lobe until then
          {"baseReflectance", "return vec3(0.04);", {}},
          {"specularBRDF", "return vec3(0.0);",
           {"D_GGX", "G1_SchlickGGX", "G_SchlickGGX", "F_Schlick", "ggxAlpha", "baseReflectance"}},
          {"diffuseBRDF", "return vec3(0.0);", {"Fd_Lambert", "F_Schlick", "baseReflectance"}},
          // Lambert alone (no light at all while 03 is not ready either).
          {"cookTorranceBRDF", "return Fd_Lambert(m.albedo);",
           {"Fd_Lambert", "D_GGX", "G1_SchlickGGX", "G_SchlickGGX", "F_Schlick", "ggxAlpha", "baseReflectance"}}}},
        {9, "09-reflections", "Fresnel-attenuated reflection bounces",
         {{"F_SchlickRoughness", "return vec3(0.0);", {}},
          // The first hit only: no reflections.
          {"traceRay",
           "Hit hit = closestHit(origin, dir, NO_SPHERE); "
           "return hit.t == NO_HIT ? backgroundRadiance() : shadeHit(hit, -dir);",
           {"F_SchlickRoughness", "baseReflectance", "offsetRayOrigin"}}}},
        {10, "10-display", "exposure, tone mapping and gamma",
         {{"toneMap", "return c;", {}},
          {"encodeGamma", "return c;", {}},
          {"displayEncode", "return radiance;", {"toneMap", "encodeGamma"}}}},  // a clamp alone (display.glsl)
    };
    return list;
}

const ExerciseInfo* exerciseOfFunction(const std::string& function) {
    for (const ExerciseInfo& e : allExercises())
        for (const ExerciseFunction& f : e.functions)
            if (f.name == function) return &e;
    return nullptr;
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
