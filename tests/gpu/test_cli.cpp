// `raylab render` as a user meets it: outputs, and one clear line with a
// non-zero exit for every bad input.
#include "core/image.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using namespace rl;

namespace {

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(Cli, RenderWritesPngAndPfmAndPrintsTheirPaths) {
    fs::path dir = test::freshTempDir("cli_render");
    auto r = test::runRaylab("render -o " + (dir / "a.png").string() + " --hdr " + (dir / "a.pfm").string() +
                             " --size 40x30");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, (dir / "a.png").string() + "\n" + (dir / "a.pfm").string() + "\n");
    DisplayImage png = readPng((dir / "a.png").string());
    EXPECT_EQ(png.width, 40);
    EXPECT_EQ(png.height, 30);
    RadianceImage pfm = readPfm((dir / "a.pfm").string());
    EXPECT_EQ(pfm.width, 40);
    EXPECT_EQ(test::readText(dir / "a.pfm").substr(0, 3), "PF\n");
}

TEST(Cli, CpuRenderIsTheSameAsGl) {
    fs::path dir = test::freshTempDir("cli_cpu");
    ASSERT_EQ(test::runRaylab("render --size 64x48 -o " + (dir / "gl.png").string()).status, 0);
    ASSERT_EQ(test::runRaylab("render --cpu --size 64x48 -o " + (dir / "cpu.png").string()).status, 0);
    Rendering gl{{}, readPng((dir / "gl.png").string())}, cpu{{}, readPng((dir / "cpu.png").string())};
    ImageDiff d = compareRenderings(gl, cpu);
    EXPECT_LE(d.offFraction, 0.005) << test::describe(d);
}

TEST(Cli, MissingSceneFile) {
    auto r = test::runRaylab("render /nonexistent/scene.json -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: /nonexistent/scene.json: scene file not found\n");
}

TEST(Cli, SceneIsADirectory) {
    fs::path dir = test::freshTempDir("cli_dir");
    auto r = test::runRaylab("render " + dir.string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + dir.string() + ": is a directory, expected a scene file (.json)\n");
}

TEST(Cli, EmptySceneFile) {
    fs::path dir = test::freshTempDir("cli_empty");
    test::writeText(dir / "empty.json", "");
    auto r = test::runRaylab("render " + (dir / "empty.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + (dir / "empty.json").string() +
                            ": the scene file is empty (expected a JSON object)\n");
}

TEST(Cli, SyntaxErrorNamesLineAndColumn) {
    fs::path dir = test::freshTempDir("cli_syntax");
    test::writeText(dir / "x.json", "{\n  \"spheres\": [\n    { \"radius\": 1 }\n  ]\n  \"lights\": []\n}\n");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output.rfind("raylab: error: " + (dir / "x.json").string() + ":5:", 0), 0u) << r.output;
    EXPECT_EQ(lines(r.output), 1) << r.output;
}

TEST(Cli, BadValueNamesTheFieldPath) {
    fs::path dir = test::freshTempDir("cli_value");
    test::writeText(dir / "x.json", R"({"spheres": [{}, {}, {}, {"radius": 0}]})");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + (dir / "x.json").string() + ": spheres[3].radius must be > 0\n");
}

TEST(Cli, UnknownKeyIsAWarningAndTheRenderGoesOn) {
    fs::path dir = test::freshTempDir("cli_unknown");
    test::writeText(dir / "x.json", R"({"render": {"width": 8, "height": 8, "resolution": 3}})");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o " + (dir / "x.png").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("raylab: warning: " + (dir / "x.json").string() +
                            ": unknown key 'render.resolution' (ignored)"),
              std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::exists(dir / "x.png"));
}

TEST(Cli, BadOptions) {
    auto size = test::runRaylab("render --size 640by480 -o /tmp/x.png");
    EXPECT_EQ(size.status, 1);
    EXPECT_EQ(size.output, "raylab: error: --size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, e.g. 640x480, "
                           "not '640by480'\n");
    auto spp = test::runRaylab("render --spp 3 -o /tmp/x.png");
    EXPECT_EQ(spp.status, 1);
    EXPECT_NE(spp.output.find("--spp: must be a square number"), std::string::npos);
    auto impl = test::runRaylab("render --impl /nonexistent -o /tmp/x.png");
    EXPECT_EQ(impl.status, 1);
    EXPECT_EQ(impl.output, "raylab: error: --impl: /nonexistent is not a directory\n");
    auto view = test::runRaylab("render --view sparkles -o /tmp/x.png");
    EXPECT_EQ(view.status, 1);
    EXPECT_NE(view.output.find("--view: unknown view 'sparkles'"), std::string::npos);
    auto unknown = test::runRaylab("render --frobnicate");
    EXPECT_NE(unknown.status, 0);
    EXPECT_NE(unknown.output.find("frobnicate"), std::string::npos);
    auto none = test::runRaylab("");
    EXPECT_NE(none.status, 0);
}

TEST(Cli, UnwritableOutputIsOneClearError) {
    auto r = test::runRaylab("render --size 8x8 -o /nonexistent/dir/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output.rfind("raylab: error: /nonexistent/dir/x.png: cannot write PNG", 0), 0u) << r.output;
    EXPECT_EQ(lines(r.output), 1);
}

TEST(Cli, EveryTeachingViewRendersWithoutNaN) {
    fs::path dir = test::freshTempDir("cli_views");
    for (std::string view : {"final", "d", "g", "f", "fnv", "diffuse", "specular", "ndotl", "shadow", "normals", "bounce0",
                             "bounce1", "bounce2"}) {
        std::string pfm = (dir / (view + ".pfm")).string();
        auto r = test::runRaylab("render --size 48x36 --view " + view + " -o " + (dir / (view + ".png")).string() +
                                 " --hdr " + pfm);
        ASSERT_EQ(r.status, 0) << view << ": " << r.output;
        RadianceImage image = readPfm(pfm);
        long bad = 0;
        for (float v : image.rgb) bad += !std::isfinite(v);
        EXPECT_EQ(bad, 0) << view;
    }
}
