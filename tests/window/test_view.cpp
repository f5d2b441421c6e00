// `raylab view` in a real window on a private Xvfb, rendered by Mesa: the
// picture, the trackball, the teaching views, the wipe, and the one-line
// errors. Pictures are checked against `raylab render` of the same camera
// and size (headless, the path every other GPU test trusts).
#include "window/view_harness.h"

#include "camera/trackball.h"
#include "core/paths.h"
#include "core/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;

namespace {

// Small windows: llvmpipe renders 160x120 in milliseconds, and every
// feature under test shows at that size. The panel hidden (--no-panel): the
// picture is then the whole window, as `raylab render` draws it (shown, the
// panel docks at the left and the picture takes the rest).
constexpr int kWidth = 160;
constexpr int kHeight = 120;
const std::string kSize = "160x120";
// The window and `raylab render` run the same shader on the same Mesa, but
// the window's camera basis comes from the trackball's quaternion and the
// file's from position/target/up: in float, a few silhouette pixels may
// flip. At most 0.5% of the pixels may differ by more than 2 LSB.
constexpr double kMaxOffFraction = 0.005;

std::string lectureScene() { return (sourceRoot() / "scenes" / "lecture.json").string(); }

class ViewTest : public ::testing::Test {
protected:
    Xvfb x;
    TempDir dir;
    std::map<std::string, std::string> env = windowEnv(x);

    // `raylab render SCENE --size 160x120 -o NAME [extra]`, read back.
    DisplayImage renderHeadless(const std::string& scene, const std::string& name,
                                std::vector<std::string> extra = {}) {
        std::vector<std::string> args = {"render", scene, "--size", kSize, "-o", name};
        args.insert(args.end(), extra.begin(), extra.end());
        RunResult r = runRaylab(args, env, dir.path());
        EXPECT_EQ(r.status, 0) << r.err;
        return readPng((dir / name).string());
    }

    // `raylab view --script` with the given script text; expects exit 0.
    RunResult view(const std::string& script, std::vector<std::string> extra = {}) {
        writeText(dir / "script.txt", script);
        std::vector<std::string> args = {"view", lectureScene(), "--size", kSize, "--no-captions", "--no-panel", "--script", "script.txt"};
        args.insert(args.end(), extra.begin(), extra.end());
        return runRaylab(args, env, dir.path());
    }

    // The lecture scene with `camera`, as a file, rendered headless.
    DisplayImage renderWithCamera(const Camera& camera, const std::string& name) {
        Scene scene = loadSceneFile(lectureScene()).scene;
        scene.camera = camera;
        saveSceneFile(scene, (dir / (name + ".json")).string());
        return renderHeadless((dir / (name + ".json")).string(), name + ".png");
    }
};

void expectSamePicture(const DisplayImage& got, const DisplayImage& expected, const std::string& what) {
    PictureDiff d = comparePictures(got, expected);
    EXPECT_LE(d.offFraction, kMaxOffFraction) << what << ": " << d.offFraction * 100 << "% of the pixels differ";
}

}  // namespace

TEST_F(ViewTest, WindowPictureMatchesHeadlessRender) {
    RunResult v = runRaylab({"view", lectureScene(), "--size", kSize, "--no-captions", "--no-panel", "--frames", "3", "--screenshot", "window.png"},
                            env, dir.path());
    ASSERT_EQ(v.status, 0) << v.err;
    EXPECT_NE(v.out.find("median"), std::string::npos) << "--frames prints the median frame time: " << v.out;
    DisplayImage window = readPng((dir / "window.png").string());
    ASSERT_EQ(window.width, kWidth);
    ASSERT_EQ(window.height, kHeight);
    expectSamePicture(window, renderHeadless(lectureScene(), "headless.png"), "window vs raylab render");
}

TEST_F(ViewTest, LeftDragRotatesAsTheTrackballPredicts) {
    RunResult v = view("wait 1\ndrag 60 50 115 72 left\nwait 1\nscreenshot dragged.png\nquit\n");
    ASSERT_EQ(v.status, 0) << v.err;

    Scene scene = loadSceneFile(lectureScene()).scene;
    Trackball predicted(scene.camera, kWidth, kHeight);
    predicted.beginDrag({60, 50}, Trackball::Mode::Rotate);
    predicted.drag({115, 72});
    predicted.endDrag();

    DisplayImage dragged = readPng((dir / "dragged.png").string());
    expectSamePicture(dragged, renderWithCamera(predicted.camera(), "predicted"), "after the drag");
    // And the drag did move the view: most pixels changed.
    PictureDiff moved = comparePictures(dragged, renderHeadless(lectureScene(), "start.png"));
    EXPECT_GT(moved.offFraction, 0.2);
}

TEST_F(ViewTest, RightDragPansAndWheelZoomsAsTheTrackballPredicts) {
    RunResult v = view("drag 80 60 100 75 right\nscroll 3\nwait 1\nscreenshot moved.png\nquit\n");
    ASSERT_EQ(v.status, 0) << v.err;

    Scene scene = loadSceneFile(lectureScene()).scene;
    Trackball predicted(scene.camera, kWidth, kHeight);
    predicted.beginDrag({80, 60}, Trackball::Mode::Pan);
    predicted.drag({100, 75});
    predicted.endDrag();
    predicted.zoom(3);

    expectSamePicture(readPng((dir / "moved.png").string()), renderWithCamera(predicted.camera(), "predicted"),
                      "after pan and zoom");
}

TEST_F(ViewTest, ResetKeyRestoresTheSceneCamera) {
    RunResult v = view("drag 40 40 120 90\nkey R\nwait 1\nscreenshot reset.png\nquit\n");
    ASSERT_EQ(v.status, 0) << v.err;
    expectSamePicture(readPng((dir / "reset.png").string()), renderHeadless(lectureScene(), "start.png"), "after R");
}

TEST_F(ViewTest, WipeShowsEachImplementationOnItsSide) {
    const std::string exercises = exercisesDir().string(), solutions = solutionsDir().string();
    RunResult v =
        view("divider 0.5\nwait 1\nscreenshot wipe.png\nquit\n", {"--impl", exercises, "--compare", solutions});
    ASSERT_EQ(v.status, 0) << v.err;
    DisplayImage wipe = readPng((dir / "wipe.png").string());
    DisplayImage left = renderHeadless(lectureScene(), "left.png", {"--impl", exercises});
    DisplayImage right = renderHeadless(lectureScene(), "right.png", {"--impl", solutions});
    const int half = kWidth / 2;
    expectSamePicture(columns(wipe, 0, half), columns(left, 0, half), "left of the divider: --impl");
    expectSamePicture(columns(wipe, half, kWidth), columns(right, half, kWidth), "right of the divider: --compare");
    // The two implementations do differ (the stubs show), so the test means something.
    EXPECT_GT(comparePictures(left, right).offFraction, 0.2);
}

TEST_F(ViewTest, NoWindowSystemIsOneClearLine) {
    std::map<std::string, std::string> noDisplay = {{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}};
    RunResult v = runRaylab({"view", lectureScene(), "--frames", "1"}, noDisplay, dir.path());
    EXPECT_NE(v.status, 0);
    EXPECT_NE(v.err.find("no window system"), std::string::npos) << v.err;
    EXPECT_EQ(std::count(v.err.begin(), v.err.end(), '\n'), 1) << v.err;
}

TEST_F(ViewTest, BadScriptFailsBeforeTheWindowOpens) {
    RunResult v = view("wait 1\njump 3\n");
    EXPECT_EQ(v.status, 1);
    EXPECT_NE(v.err.find("script.txt:2: unknown command 'jump'"), std::string::npos) << v.err;
    EXPECT_EQ(std::count(v.err.begin(), v.err.end(), '\n'), 1) << v.err;
    RunResult key = view("key Z\n");
    EXPECT_EQ(key.status, 1);
    EXPECT_NE(key.err.find("script.txt:1: unknown key 'Z'"), std::string::npos) << key.err;
}

// Every teaching view: no NaN or Inf in the radiance (headless, --hdr), and
// the window shows the same picture when the view is selected there.
class TeachingViewTest : public ViewTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(TeachingViewTest, RendersFiniteAndTheWindowShowsIt) {
    const std::string view = GetParam();
    DisplayImage headless =
        renderHeadless(lectureScene(), view + ".png", {"--view", view, "--hdr", (dir / (view + ".pfm")).string()});
    RadianceImage radiance = readPfm((dir / (view + ".pfm")).string());
    long nonFinite = 0;
    for (float v : radiance.rgb) nonFinite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(nonFinite, 0) << view << ": NaN or Inf in the radiance";

    RunResult v = runRaylab({"view", lectureScene(), "--size", kSize, "--no-captions", "--no-panel", "--view", view, "--frames", "1", "--screenshot",
                             "window-" + view + ".png"},
                            env, dir.path());
    ASSERT_EQ(v.status, 0) << v.err;
    expectSamePicture(readPng((dir / ("window-" + view + ".png")).string()), headless, "view " + view);
}

INSTANTIATE_TEST_SUITE_P(Views, TeachingViewTest,
                         ::testing::Values("final", "d", "g", "f", "fnv", "diffuse", "specular", "ndotl", "shadow", "normals",
                                           "bounce0", "bounce1", "bounce2"));

TEST_F(ViewTest, NumberKeysSelectTheViews) {
    RunResult v = view("key 8\nwait 1\nscreenshot normals.png\nkey 9\nkey ]\nwait 1\nscreenshot bounce2.png\nquit\n");
    ASSERT_EQ(v.status, 0) << v.err;
    expectSamePicture(readPng((dir / "normals.png").string()),
                      renderHeadless(lectureScene(), "h-normals.png", {"--view", "normals"}), "key 8");
    expectSamePicture(readPng((dir / "bounce2.png").string()),
                      renderHeadless(lectureScene(), "h-bounce2.png", {"--view", "bounce2"}), "keys 9 and ]");
}

// The same drag and keys through the X server (xdotool), not the script:
// GLFW's callbacks, the screen-to-pixel conversion, P (screenshot) and Q.
TEST_F(ViewTest, RealMouseAndKeysThroughTheWindowSystem) {
    Process viewer({RAYLAB_BINARY, "view", lectureScene(), "--size", kSize, "--no-panel", "--no-captions", "--view", "normals"}, env,
                   dir.path());
    auto xdotool = [&](std::vector<std::string> args) {
        args.insert(args.begin(), "xdotool");
        return Process(args, env, dir.path()).wait(std::chrono::seconds(60));
    };
    RunResult found = xdotool({"search", "--sync", "--onlyvisible", "--name", "raylab view"});
    ASSERT_EQ(found.status, 0) << "the window did not appear: " << found.err;
    const std::string window = found.out.substr(0, found.out.find('\n'));
    RunResult input = xdotool({"mousemove", "--window", window, "60",  "50", "mousedown", "1",  //
                               "mousemove", "--window", window, "90",  "60",                    //
                               "mousemove", "--window", window, "115", "72", "mouseup",   "1", "key", "p"});
    ASSERT_EQ(input.status, 0) << input.err;
    // P writes raylab-DATE-TIME.png into the working directory.
    fs::path shot;
    for (int tries = 0; tries < 3000 && shot.empty(); ++tries) {
        for (const auto& entry : fs::directory_iterator(dir.path()))
            if (entry.path().filename().string().rfind("raylab-", 0) == 0 && entry.path().extension() == ".png")
                shot = entry.path();
        if (shot.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(shot.empty()) << "no screenshot after P";
    waitForFile(shot, std::chrono::seconds(1));
    ASSERT_EQ(xdotool({"key", "q"}).status, 0);
    RunResult r = viewer.wait(std::chrono::seconds(60));
    ASSERT_EQ(r.status, 0) << r.err;

    Scene scene = loadSceneFile(lectureScene()).scene;
    Trackball predicted(scene.camera, kWidth, kHeight);
    predicted.beginDrag({60, 50}, Trackball::Mode::Rotate);
    predicted.drag({115, 72});
    predicted.endDrag();
    scene.camera = predicted.camera();
    saveSceneFile(scene, (dir / "predicted.json").string());
    expectSamePicture(readPng(shot.string()),
                      renderHeadless((dir / "predicted.json").string(), "predicted.png", {"--view", "normals"}),
                      "real drag, then P");
}

// --compare-model: the same scene and code, Blinn-Phong right of the divider.
// The metallic row, where the two highlights differ most.
TEST_F(ViewTest, BlinnPhongWipeAgainstPbr) {
    const std::string row = (sourceRoot() / "scenes" / "presets" / "02-metallic-0-to-1.json").string();
    writeText(dir / "script.txt", "divider 0.5\nwait 1\nscreenshot wipe.png\nquit\n");
    RunResult v = runRaylab({"view", row, "--size", kSize, "--no-captions", "--no-panel", "--compare-model", "blinn-phong", "--script", "script.txt"},
                            env, dir.path());
    ASSERT_EQ(v.status, 0) << v.err;
    Scene blinnPhong = loadSceneFile(row).scene;
    blinnPhong.model.blinnPhong = true;
    saveSceneFile(blinnPhong, (dir / "blinn-phong.json").string());
    DisplayImage wipe = readPng((dir / "wipe.png").string());
    DisplayImage pbr = renderHeadless(row, "pbr.png");
    DisplayImage phong = renderHeadless((dir / "blinn-phong.json").string(), "phong.png");
    const int half = kWidth / 2;
    expectSamePicture(columns(wipe, 0, half), columns(pbr, 0, half), "left: the scene's model (PBR)");
    expectSamePicture(columns(wipe, half, kWidth), columns(phong, half, kWidth), "right: Blinn-Phong");
    // The models differ (in the highlights: about 6% of the right half), by
    // far more than the budget, so the right half tells them apart.
    EXPECT_GT(comparePictures(columns(pbr, half, kWidth), columns(phong, half, kWidth)).offFraction,
              4 * kMaxOffFraction);
}
