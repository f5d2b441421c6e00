// The live view's environment sliders (issue 24): intensity and rotation are
// values the program reads as uniforms (u_envIntensity, u_envRotation), so
// dragging them re-renders without building a program, and the picture is
// what `raylab render` draws for a scene file with those values.
#include "window/view_harness.h"

#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/scene_uniforms.h"
#include "view/view_caption.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;

namespace {
// As tests/window/test_view.cpp: the window's camera comes from the
// trackball's quaternion, the file's from position/target/up; in float a few
// silhouette pixels may flip. At most 0.5% of the pixels off by over 2 LSB.
constexpr double kMaxOffFraction = 0.005;
}  // namespace

TEST(ViewEnvironment, RotationAndIntensitySlidersNeverRecompile) {
    Xvfb x(320, 240);
    TempDir dir;
    const auto env = windowEnv(x);
    const fs::path sceneFile = scenesDir() / "environments" / "sky-spheres.json";
    writeText(dir / "s.txt",
              "wait 2\nscreenshot before.png\n"
              "slide env-rotation 0 90 6\nslide env-intensity 1 2 4\n"
              "wait 3\nscreenshot after.png\nquit\n");
    RunResult r = runRaylab({"view", sceneFile.string(), "--size", "160x90", "--no-panel", "--no-captions", "--script",
                             "s.txt"},
                            env, dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    // A program built after the first would print "raylab: built ... for ..."
    // (view_app.cpp); the still picture's program is built once, at the
    // first frame at rest: the environment's rotation and intensity are
    // uniforms even there.
    const std::string still = "raylab: built solutions for the still picture";
    const std::size_t first = r.out.find("raylab: built ");
    EXPECT_EQ(r.out.find(still), first) << r.out;
    EXPECT_EQ(r.out.find("raylab: built ", first + 1), std::string::npos) << r.out;

    // The same values written in a scene file, rendered headless.
    std::string text = readText(sceneFile);
    const std::string from = "\"environment\": { \"file\": \"sky.hdr\", \"intensity\": 1.0, \"rotation\": 0 }";
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << "the test edits this line of " << sceneFile;
    text.replace(at, from.size(),
                 "\"environment\": { \"file\": \"" + (scenesDir() / "environments" / "sky.hdr").string() +
                     "\", \"intensity\": 2.0, \"rotation\": 90 }");
    writeText(dir / "turned.json", text);
    RunResult rendered = runRaylab({"render", "turned.json", "--size", "160x90", "-o", "expected.png"}, env, dir.path());
    ASSERT_EQ(rendered.status, 0) << rendered.err;

    const DisplayImage before = readPng((dir / "before.png").string());
    const DisplayImage after = readPng((dir / "after.png").string());
    const DisplayImage expected = readPng((dir / "expected.png").string());
    EXPECT_GT(comparePictures(before, after).offFraction, 0.2) << "the sliders changed the picture";
    const PictureDiff d = comparePictures(after, expected);
    std::printf("env sliders: after vs render of the same values: %.4f off, max %d LSB\n", d.offFraction, d.maxLsb);
    EXPECT_LE(d.offFraction, kMaxOffFraction);
}

// The environment's teaching views (shaders/views.glsl): each has a name for
// --view, a key, a caption with a colour bar, and draws its term on a scene
// with an environment; a scene without one draws black and its caption says why.
TEST(ViewEnvironment, TermViewsRenderWithCaptionsAndAreBlackWithoutAnEnvironment) {
    TempDir dir;
    const Scene studio = loadSceneFile((scenesDir() / "environments" / "studio-spheres.json").string()).scene;
    const Scene lecture = loadSceneFile((scenesDir() / "lecture.json").string()).scene;
    const std::map<std::string, std::string> env;
    for (const char* name : {"irradiance", "prefiltered", "env-scale", "env-bias"}) {
        SCOPED_TRACE(name);
        int bounce = -1;
        const View view = parseView(name, bounce);
        EXPECT_EQ(viewName(view), name);
        const ViewCaption caption = viewCaption(view, 0, studio, ShadingModel{});
        EXPECT_FALSE(caption.formula.empty());
        EXPECT_GE(caption.scale.ticks.size(), 2u);
        EXPECT_EQ(caption.title.find("no environment"), std::string::npos);
        EXPECT_NE(viewCaption(view, 0, lecture, ShadingModel{}).title.find("this scene has no environment: black"),
                  std::string::npos);

        RunResult withEnvironment = runRaylab({"render", (scenesDir() / "environments" / "studio-spheres.json").string(),
                                               "--size", "64x36", "--view", name, "-o", "env.png"},
                                              env, dir.path());
        ASSERT_EQ(withEnvironment.status, 0) << withEnvironment.err;
        RunResult without = runRaylab({"render", (scenesDir() / "lecture.json").string(), "--size", "64x36", "--view",
                                       name, "-o", "none.png"},
                                      env, dir.path());
        ASSERT_EQ(without.status, 0) << without.err;
        const DisplayImage lit = readPng((dir / "env.png").string());
        const DisplayImage black = readPng((dir / "none.png").string());
        long litPixels = 0, nonBlack = 0;
        for (std::size_t i = 0; i < lit.rgb.size(); ++i) litPixels += lit.rgb[i] > 8;
        for (std::size_t i = 0; i < black.rgb.size(); ++i) nonBlack += black.rgb[i] > 0;
        // The spheres and the floor fill most of the frame; even the bias
        // (small but for grazing angles) lights the rims and the floor's far part.
        EXPECT_GT(litPixels, long(lit.rgb.size() / 50)) << "the term is drawn";
        EXPECT_EQ(nonBlack, 0) << "no environment: black";
    }
}
