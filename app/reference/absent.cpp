// The reference layer of a student edition: scripts/student-edition.sh
// leaves out the model's sources (brdf_reference.cpp, cpu_reference.cpp,
// environment_reference.cpp, pixel_breakdown.cpp, split_sum.cpp, the units'
// reference.cpp), and CMakeLists.txt compiles this file in their place. Each
// function the program calls says, as one line, that it is not in this copy;
// the checker reads what the instructor's build recorded instead (its probes'
// expected values, the check scenes' pictures: checks/probe_data.h,
// checks/checker.h), and so does splitSumTable() here, for the table the
// environment light's default settings use (docs/instructor.md, "A student
// edition"; docs/decisions.md, "What the student edition ships").
#include "reference/cpu_reference.h"
#include "reference/pixel_breakdown.h"
#include "reference/split_sum.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/json_text.h"
#include "core/paths.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace rl::ref {

namespace {

[[noreturn]] void absent(const std::string& what) {
    throw Error("not in this copy: " + what +
                " needs the CPU reference, which a student edition leaves out (its sources are the model)");
}

}  // namespace

bool referenceInThisCopy() { return false; }

// The framework's roughness convention, not a term of the model (exercise
// 08's stub states it, shaders/common.glsl has MIN_ROUGHNESS): the picture's
// bounce cutoff (render/bounce_cutoff.cpp) needs it to render.
double clampRoughness(double roughness) { return std::clamp(roughness, kMinRoughness, 1.0); }

Rendering renderCpu(const Scene&, int) { absent("rendering with --cpu"); }
Rendering renderCpu(const Scene&, int, const EnvironmentOptions&) { absent("rendering with --cpu"); }
PixelTerms explainPixel(const Scene&, const Camera&, int, int, int, int, const EnvironmentTables*) { absent("asking a pixel"); }
std::string formatPixelTerms(const Scene&, const PixelTerms&) { absent("asking a pixel"); }
glm::dvec3 displayEncode(glm::dvec3, const RenderSettings&) { absent("this value"); }
glm::dvec2 sampleOffset(int, int) { absent("this value"); }
double ggxAlpha(double) { absent("this value"); }
glm::dvec3 baseReflectance(const Material&) { absent("this value"); }
double D_GGX(glm::dvec3, glm::dvec3, double) { absent("this value"); }
double G_SchlickGGX(double, double, double) { absent("this value"); }
glm::dvec3 F_Schlick(glm::dvec3, double) { absent("this value"); }
glm::dvec3 Fd_Lambert(glm::dvec3) { absent("this value"); }
glm::dvec3 specularBRDF(glm::dvec3, glm::dvec3, glm::dvec3, const Material&) { absent("this value"); }
glm::dvec3 diffuseBRDF(glm::dvec3, glm::dvec3, glm::dvec3, const Material&) { absent("this value"); }
glm::dvec3 cookTorranceBRDF(glm::dvec3, glm::dvec3, glm::dvec3, const Material&) { absent("this value"); }

// The split-sum table of the default settings (32 x 32 entries, 32^2 half
// vectors each), as the instructor's build recorded it (`raylab course
// --record`): recorded/split-sum-32-32.json, every entry's scale and bias.
std::vector<glm::dvec2> splitSumTable(int size, int samples) {
    const std::filesystem::path file =
        sourceRoot() / "recorded" / ("split-sum-" + std::to_string(size) + "-" + std::to_string(samples) + ".json");
    if (!std::filesystem::is_regular_file(file))
        absent("the split-sum table of " + std::to_string(size) + " x " + std::to_string(size) + " entries and " +
               std::to_string(samples) + " samples (only the default 32 and 32 is recorded, " + file.string() + ")");
    const nlohmann::json j = parseJsonText(readRegularFile(file, 1u << 20), file.string());
    std::vector<glm::dvec2> table;
    if (!j.is_array() || j.size() != std::size_t(size) * std::size_t(size) * 2)
        throw Error(file.string() + ": not " + std::to_string(size * size) + " pairs of numbers");
    for (std::size_t k = 0; k < j.size(); k += 2) {
        if (!j[k].is_number() || !j[k + 1].is_number()) throw Error(file.string() + ": not a list of numbers");
        table.emplace_back(j[k].get<double>(), j[k + 1].get<double>());
    }
    return table;
}

}  // namespace rl::ref
