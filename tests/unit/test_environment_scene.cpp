// The scene's optional "environment" (issue 24, docs/scene-format.md): the
// field, its path relative to the scene file, and one line naming both files
// for every image that cannot be used.
#include "core/error.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

using namespace rl;
namespace fs = std::filesystem;

namespace {

// A PFM of the given size, every value `value` (little endian, as the project writes them).
void writePfmFile(const fs::path& path, int width, int height, float value) {
    std::string data = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    for (long k = 0; k < 3L * width * height; ++k) data.append(reinterpret_cast<const char*>(&value), 4);
    std::ofstream(path, std::ios::binary) << data;
}

std::string loadError(const fs::path& scene) {
    try {
        loadSceneFile(scene.string());
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

fs::path sceneWith(const fs::path& dir, const std::string& environment) {
    fs::path scene = dir / "scene.json";
    test::writeText(scene, "{\"environment\": " + environment + "}");
    return scene;
}

}  // namespace

TEST(EnvironmentScene, ReadsEveryFieldRelativeToTheSceneFile) {
    fs::path dir = test::freshTempDir("env-fields");
    fs::create_directories(dir / "maps");
    writePfmFile(dir / "maps" / "grey.pfm", 8, 4, 0.25f);
    fs::create_directories(dir / "sub");
    fs::path scene = dir / "sub" / "scene.json";
    test::writeText(scene, R"({"environment": {"file": "../maps/grey.pfm", "intensity": 3, "rotation": -45}})");
    LoadedScene loaded = loadSceneFile(scene.string());
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_TRUE(loaded.scene.environment.has_value());
    const Environment& e = *loaded.scene.environment;
    EXPECT_EQ(e.file, "../maps/grey.pfm");
    EXPECT_EQ(fs::weakly_canonical(e.path), fs::weakly_canonical(dir / "maps" / "grey.pfm"));
    EXPECT_EQ(e.intensity, 3.0);
    EXPECT_EQ(e.rotationDegrees, -45.0);
    ASSERT_TRUE(e.image);
    EXPECT_EQ(e.image->width, 8);
    EXPECT_EQ(e.image->rgb[5], 0.25f);

    // Defaults; an unknown key is a warning as everywhere else.
    test::writeText(scene, R"({"environment": {"file": "../maps/grey.pfm", "blur": 2}})");
    loaded = loadSceneFile(scene.string());
    EXPECT_EQ(loaded.scene.environment->intensity, 1.0);
    EXPECT_EQ(loaded.scene.environment->rotationDegrees, 0.0);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("environment.blur"), std::string::npos) << loaded.warnings[0];
}

TEST(EnvironmentScene, SavedSceneKeepsPointingAtTheSameImage) {
    fs::path dir = test::freshTempDir("env-save");
    writePfmFile(dir / "grey.pfm", 8, 4, 0.5f);
    fs::path scene = sceneWith(dir, R"({"file": "grey.pfm", "intensity": 2, "rotation": 10})");
    Scene s = loadSceneFile(scene.string()).scene;
    fs::create_directories(dir / "elsewhere");
    fs::path copy = dir / "elsewhere" / "copy.json";
    saveSceneFile(s, copy.string());
    nlohmann::json j = nlohmann::json::parse(test::readText(copy));
    EXPECT_EQ(j["environment"]["file"], "../grey.pfm");
    EXPECT_EQ(j["environment"]["intensity"], 2.0);
    EXPECT_EQ(j["environment"]["rotation"], 10.0);
    Scene again = loadSceneFile(copy.string()).scene;
    EXPECT_EQ(again.environment->image->rgb, s.environment->image->rgb);
    // Without an environment nothing is written: old scenes save byte for byte as before.
    EXPECT_FALSE(sceneToJson(defaultScene()).contains("environment"));
}

TEST(EnvironmentScene, EveryBadImageIsOneLineNamingTheSceneAndTheImage) {
    fs::path dir = test::freshTempDir("env-bad");
    struct Case {
        const char* what;
        std::string field;
        std::function<void()> prepare;
        const char* expected;
    };
    std::vector<Case> cases = {
        {"missing", R"({"file": "nowhere.hdr"})", [] {}, "not found"},
        {"a folder", R"({"file": "folder.hdr"})", [&] { fs::create_directories(dir / "folder.hdr"); }, "directory"},
        {"not an image", R"({"file": "text.hdr"})", [&] { test::writeText(dir / "text.hdr", "hello"); },
         "neither a Radiance .hdr"},
        {"truncated hdr", R"({"file": "cut.hdr"})",
         [&] { test::writeText(dir / "cut.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n\x02\x02"); },
         "cannot read the environment image"},
        // stb_image alone loops forever on this one (found by mutating sky.hdr;
        // it reads zeros past the end, a run of length 0 that never ends)...
        {"hdr cut short", R"({"file": "cut-sky.hdr"})",
         [&] {
             std::string sky = test::readText(rl::scenesDir() / "environments" / "sky.hdr");
             test::writeText(dir / "cut-sky.hdr", sky.substr(0, 129384));
         },
         "corrupt HDR: the file ends at scanline 124"},
        // ...and reports this one as "bad RLE data in HDR" by luck of the next byte.
        {"hdr with a run of 0", R"({"file": "zero-run.hdr"})",
         [&] {
             std::string sky = test::readText(rl::scenesDir() / "environments" / "sky.hdr");
             std::size_t start = sky.find("+X 256\n") + 7;  // the first scanline: 2 2 1 0, then its first run
             sky[start + 4] = '\0';  // the first run of the first scanline
             test::writeText(dir / "zero-run.hdr", sky);
         },
         "corrupt HDR: a run of length 0 at scanline 0"},
        {"oversized hdr", R"({"file": "huge.hdr"})",
         [&] { test::writeText(dir / "huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4096 +X 4096\n"); },
         "more than the limit"},
        {"oversized pfm", R"({"file": "wide.pfm"})", [&] { writePfmFile(dir / "wide.pfm", 4097, 1, 1.0f); },
         "more than the limit"},
        {"negative radiance", R"({"file": "negative.pfm"})", [&] { writePfmFile(dir / "negative.pfm", 4, 2, -1.0f); },
         "must be finite, >= 0"},
        {"bad pfm", R"({"file": "short.pfm"})", [&] { test::writeText(dir / "short.pfm", "PF\n4 2\n-1.0\n"); },
         "a PFM (expected 96 bytes"},
        {"no file", R"({"intensity": 2})", [] {}, "environment.file is missing"},
        {"empty file", R"({"file": ""})", [] {}, "environment.file must name"},
        {"negative intensity", R"({"file": "x.pfm", "intensity": -1})", [] {}, "environment.intensity must be between"},
        {"not an object", R"("sky.hdr")", [] {}, "environment must be an object"},
    };
    for (const Case& c : cases) {
        c.prepare();
        fs::path scene = sceneWith(dir, c.field);
        std::string message = loadError(scene);
        EXPECT_EQ(message.rfind(scene.string() + ": ", 0), 0u) << c.what << ": " << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.what << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << c.what << ": " << message;
        if (c.field.find("\"file\": \"") != std::string::npos && c.field.find("\"\"") == std::string::npos &&
            c.field.find("intensity\": -1") == std::string::npos) {
            std::string file = nlohmann::json::parse(c.field)["file"];
            EXPECT_NE(message.find(file), std::string::npos) << c.what << " should name " << file << ": " << message;
        }
    }
}

// As a user runs it: the command refuses the scene in one line, non-zero, and writes nothing.
TEST(EnvironmentScene, TheRenderCommandRefusesAMissingImage) {
    fs::path dir = test::freshTempDir("env-cli");
    fs::path scene = sceneWith(dir, R"({"file": "gone.hdr"})");
    fs::path out = dir / "out.png";
    test::CommandResult r = test::runRaylab("render --cpu " + scene.string() + " -o " + out.string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find(scene.string() + ": environment.file 'gone.hdr': "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gone.hdr: cannot read the environment image (not found)"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(EnvironmentScene, TheShippedEnvironmentScenesRender) {
    // The shipped example renders with its environment on the CPU (small, for speed).
    fs::path dir = test::freshTempDir("env-shipped");
    fs::path scene = rl::scenesDir() / "environments" / "sky-spheres.json";
    test::CommandResult r =
        test::runRaylab("render --cpu --size 16x9 " + scene.string() + " -o " + (dir / "sky.png").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "sky.png"));
}

// The shipped images are what the committed generator makes, byte for byte
// (as a user regenerates them: the command of docs/scene-format.md).
TEST(EnvironmentScene, TheShippedImagesAreTheGeneratorsOutput) {
    fs::path dir = test::freshTempDir("env-generator");
    test::CommandResult r = test::runShell("python3 '" + (rl::sourceRoot() / "scripts/make-environments.py").string() +
                                           "' '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* name : {"sky.hdr", "studio.hdr", "white.pfm"})
        EXPECT_EQ(test::readText(dir / name), test::readText(rl::scenesDir() / "environments" / name))
            << name << " differs from what scripts/make-environments.py makes";
}
