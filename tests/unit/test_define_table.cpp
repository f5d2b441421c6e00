// The table of every RL_ define (app/render/define_table.h): it and the RL_
// names of shaders/ agree both ways, its own columns are consistent, and
// definesFor() gives for every bundled scene, implementation and purpose the
// defines recorded in tests/unit/defines.golden. The golden file was written
// when definesFor() had been compared with the fourteen functions it
// replaced (equal on 12240 define sets: every scene with its own model and
// five variants, nine implementations, every purpose, the sky programs and
// the bench's layer rows; that test left with those functions, see the
// history of tests/unit/test_define_table_vs_old.cpp).
// RAYLAB_UPDATE_DEFINES_GOLDEN=1 rewrites it after a deliberate change,
// which its diff then shows.
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/define_table.h"
#include "render/implementation_facts.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace rl;
namespace fs = std::filesystem;

namespace {

// The text with // and /* */ comments blanked out: a name in a comment is no use.
std::string withoutComments(const std::string& text) {
    std::string out = text;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            std::size_t end = out.find("*/", i + 2);
            end = end == std::string::npos ? out.size() : end + 2;
            for (; i < end; ++i)
                if (out[i] != '\n') out[i] = ' ';
        }
    }
    return out;
}

// Every RL_ identifier in the code of the shader sources under `dir`
// (#ifdef, #if defined, #ifndef, #define and plain uses alike), with the
// first file it is in.
std::map<std::string, std::string> rlNamesIn(const fs::path& dir) {
    static const std::regex kName(R"(\bRL_[A-Z0-9_]+\b)");
    std::map<std::string, std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        const std::string code = withoutComments(test::readText(entry.path()));
        for (std::sregex_iterator it(code.begin(), code.end(), kName), end; it != end; ++it)
            names.emplace(it->str(), entry.path().lexically_relative(dir).string());
    }
    return names;
}

// Where the table and the shaders under `dir` disagree, one line each.
std::vector<std::string> disagreements(const fs::path& dir) {
    const std::map<std::string, std::string> used = rlNamesIn(dir);
    std::set<std::string> known(nonSpecialisationNames().begin(), nonSpecialisationNames().end());
    std::vector<std::string> out;
    for (const DefineRow& row : defineTable()) {
        const std::string name = glslName(row);
        known.insert(name);
        if (row.glsl && !used.count(name)) out.push_back(name + ": a row of the define table that no shader reads");
        if (!row.glsl && used.count(name)) out.push_back(name + ": a host-only row that " + used.at(name) + " reads");
    }
    for (const char* name : nonSpecialisationNames())
        if (!used.count(name)) out.push_back(std::string(name) + ": listed as a non-specialisation name, in no shader");
    for (const auto& [name, file] : used)
        if (!known.count(name))
            out.push_back(name + " (" + file + "): in no row of the define table (app/render/define_table.cpp) "
                                              "and not listed in nonSpecialisationNames()");
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

}  // namespace

TEST(DefineTable, AgreesWithTheShadersBothWays) {
    EXPECT_EQ(joined(disagreements(shadersDir())), "");
}

// The check above fails on a name the table does not know: a copy of
// shaders/ with one more file that tests a made-up define.
TEST(DefineTable, AnUnknownNameInTheShadersIsReported) {
    const fs::path copy = test::freshTempDir("define_table_shaders");
    fs::copy(shadersDir(), copy / "shaders", fs::copy_options::recursive);
    test::writeText(copy / "shaders" / "planted.glsl", "#ifdef RL_PLANTED_UNKNOWN\nfloat x;\n#endif\n");
    const std::vector<std::string> found = disagreements(copy / "shaders");
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find("RL_PLANTED_UNKNOWN (planted.glsl)"), std::string::npos) << found[0];
}

TEST(DefineTable, ColumnsAreConsistent) {
    std::set<std::string> above;
    for (const DefineRow& row : defineTable()) {
        SCOPED_TRACE(row.name);
        EXPECT_TRUE(above.insert(row.name).second) << "two rows of one name";
        EXPECT_EQ(row.name.rfind("RL_", 0), 0u);
        EXPECT_NE(row.purposes, 0u);
        EXPECT_EQ(row.purposes >> kPurposeCount, 0u);
        EXPECT_NE(row.dependsOn, 0u);
        EXPECT_GT(std::string(row.reason).size(), 20u);
        EXPECT_NE(row.value, nullptr);
        for (const std::string& name : row.needs) EXPECT_TRUE(above.count(name)) << "needs " << name << ", not a row above";
        for (const std::string& name : row.excludes) EXPECT_TRUE(above.count(name)) << "excludes " << name << ", not above";
        if (row.benchWith) {
            EXPECT_EQ(row.layer, BenchLayer::Without);
        }
    }
}

// ---- what definesFor() gives, against tests/unit/defines.golden ----------------------------

namespace {

std::vector<fs::path> sceneFiles() {
    std::vector<fs::path> out;
    for (const fs::path& dir : {scenesDir(), scenesDir() / "presets", scenesDir() / "hard", sourceRoot() / "tests" / "bench"})
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
                out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

// Implementations that reach every implementation-derived row: the course's
// files, the stubs, and one student's file at each place the table asks
// whether a file is the course's (01, 02, 04, 09) or finished (05).
struct Case {
    const char* name;
    Implementation impl;
};
std::vector<Case> implementations() {
    const fs::path course = sourceRoot() / "course";
    return {
        {"solutions", {solutionsDir(), {}}},
        {"stubs", {exercisesDir(), {}}},
        {"stubs+course-09", {exercisesDir(), {{"09-reflections.glsl", solutionsDir() / "09-reflections.glsl"}}}},
        {"student-01", {solutionsDir(), {{"01-camera.glsl", course / "01-camera" / "mutants" / "aspect-on-y.glsl"}}}},
        {"student-02", {solutionsDir(), {{"02-intersect.glsl", course / "02-intersect" / "mutants" / "far-root-first.glsl"}}}},
        {"student-04", {solutionsDir(), {{"04-shadows.glsl", course / "04-shadows" / "mutants" / "offset-into-surface.glsl"}}}},
        {"stub-05", {solutionsDir(), {{"05-ggx.glsl", exercisesDir() / "05-ggx.glsl"}}}},
        {"student-09", {solutionsDir(), {{"09-reflections.glsl", course / "09-reflections" / "mutants" / "full-strength-bounces.glsl"}}}},
    };
}

// FNV-1a, 64 bits: long values (the shadow cones' arrays) by their hash.
std::string shortValue(const std::string& value) {
    constexpr std::size_t kLongest = 40;
    if (value.size() <= kLongest) return value;
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : value) h = (h ^ c) * 1099511628211ull;
    char text[48];
    std::snprintf(text, sizeof text, "<%zu chars, fnv1a %016llx>", value.size(), static_cast<unsigned long long>(h));
    return text;
}

std::string line(const std::string& scene, const std::string& what, const std::string& impl, const ShaderDefines& d) {
    std::string out = scene + " " + what + " " + impl + ":";
    // Values computed in double through square roots and dot products, whose
    // last digit follows the compiler's floating-point contraction (the
    // sanitizer build prints others): recorded by name only; the accuracy
    // and differential tests check the pictures they give.
    auto computed = [](const std::string& name) {
        for (const char* prefix : {"RL_SPHERE_ANCHOR_C", "RL_CAMERA_SPHERE", "RL_LIGHT_OCCLUDER", "RL_CAMERA_RIGHT",
                                   "RL_CAMERA_UP", "RL_CAMERA_BACK"})
            if (name.rfind(prefix, 0) == 0) return true;
        return false;
    };
    for (const auto& [name, value] : d) out += " " + name + "=" + (computed(name) ? std::string("<computed>") : shortValue(value));
    return out + "\n";
}

// One line per scene, purpose and (where the purpose reads the files) set
// of implementations with equal defines; the sky tiles' programs after the pictures.
std::string definesReport() {
    std::string out;
    const std::vector<Case> impls = implementations();
    std::vector<ImplementationFacts> facts;
    for (const Case& c : impls) facts.push_back(implementationFacts(c.impl));
    for (const fs::path& file : sceneFiles()) {
        const Scene scene = loadSceneFile(file.string()).scene;
        const std::string name = file.lexically_relative(sourceRoot()).string();
        for (Purpose p : {Purpose::Generic, Purpose::GenericPicture, Purpose::EveryView, Purpose::PixelDebug})
            out += line(name, purposeName(p), "-", definesFor(scene, ImplementationFacts{}, p));
        // The implementations with equal defines on one line ("solutions,student-09").
        std::vector<std::pair<std::string, ShaderDefines>> picture, sky, live, still;
        auto group = [](std::vector<std::pair<std::string, ShaderDefines>>& into, const char* impl, ShaderDefines d) {
            for (auto& [names, defines] : into)
                if (defines == d) return void(names += std::string(",") + impl);
            into.push_back({impl, std::move(d)});
        };
        for (std::size_t i = 0; i < impls.size(); ++i) {
            ShaderDefines p = definesFor(scene, facts[i], Purpose::Picture);
            if (std::optional<ShaderDefines> s = skyProgramDefines(p)) group(sky, impls[i].name, *s);
            group(picture, impls[i].name, std::move(p));
            group(live, impls[i].name, definesFor(scene, facts[i], Purpose::LiveView));
            group(still, impls[i].name, definesFor(scene, facts[i], Purpose::LiveStill));
        }
        for (const auto& [names, d] : picture) out += line(name, "picture", names, d);
        for (const auto& [names, d] : sky) out += line(name, "sky", names, d);
        for (const auto& [names, d] : live) out += line(name, "live-view", names, d);
        for (const auto& [names, d] : still) out += line(name, "live-still", names, d);
    }
    for (std::size_t i = 0; i < impls.size(); ++i)
        out += line("-", "probe", impls[i].name, definesFor(Scene{}, facts[i], Purpose::Probe));
    return out;
}

}  // namespace

TEST(DefineTable, DefinesAsRecordedForEveryBundledScene) {
    const fs::path golden = sourceRoot() / "tests" / "unit" / "defines.golden";
    const std::string report = definesReport();
    if (const char* update = std::getenv("RAYLAB_UPDATE_DEFINES_GOLDEN"); update && std::string(update) == "1")
        test::writeText(golden, report);
    const std::string expected = test::readText(golden);
    std::istringstream got(report), want(expected);
    std::string a, b;
    int lineNo = 0, differences = 0;
    while (std::getline(want, b)) {
        ++lineNo;
        if (!std::getline(got, a)) a = "(no line)";
        if (a != b && ++differences <= 5) ADD_FAILURE() << "defines.golden:" << lineNo << "\n  want " << b << "\n  got  " << a;
    }
    if (std::getline(got, a)) ADD_FAILURE() << "more lines than defines.golden, from: " << a;
    EXPECT_EQ(differences, 0);
}
