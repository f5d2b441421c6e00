// Hot reload while the window runs: shader files (replaced by rename, as
// vim and many IDEs save; in-place edits are covered by the FileWatcher
// tests in test_view_parts.cpp), a shader that stops compiling
// (the last picture stays, the error is on screen and in the terminal as
// file:line:), scene files (good and broken), and saving the edited scene.
// Each test copies what it edits to a temp folder; the script waits for
// the reload with `wait-reload`, so no test sleeps for a guessed time.
#include "window/view_harness.h"

#include "camera/trackball.h"
#include "core/paths.h"
#include "core/scene_io.h"

#include <gtest/gtest.h>

#include <regex>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;

namespace {

const std::string kSize = "160x120";
constexpr double kMaxOffFraction = 0.005;  // as in test_view.cpp
// Generous: under a parallel ctest on two cores a frame can take a while;
// a passing run takes well under a second per reload.
constexpr auto kStart = std::chrono::seconds(90);
constexpr auto kFinish = std::chrono::seconds(120);

class ReloadTest : public ::testing::Test {
protected:
    Xvfb x;
    TempDir dir;
    std::map<std::string, std::string> env = windowEnv(x);
    fs::path impl = dir / "impl";
    fs::path scene = dir / "scene.json";

    void SetUp() override {
        fs::create_directories(impl);
        for (const auto& entry : fs::directory_iterator(solutionsDir()))
            fs::copy(entry.path(), impl / entry.path().filename());
        fs::copy(sourceRoot() / "scenes" / "lecture.json", scene);
    }

    std::unique_ptr<Process> startView(const std::string& script, std::vector<std::string> extra = {}) {
        writeText(dir / "script.txt", script);
        std::vector<std::string> args = {RAYLAB_BINARY, "view",          scene.string(), "--impl",    impl.string(),
                                         "--size",      kSize,           "--no-captions", "--no-panel", "--script", "script.txt"};
        args.insert(args.end(), extra.begin(), extra.end());
        return std::make_unique<Process>(args, env, dir.path());
    }

    DisplayImage picture(const std::string& name) { return readPng((dir / name).string()); }

    // Writes `file` in one step (a new file renamed over it). An in-place
    // write is two steps (truncate, write); on a loaded machine the watcher
    // can see the empty file in between, reload it (an error), and the
    // script's wait-reload would end on that reload. The watcher's unit
    // tests cover in-place edits.
    static void replaceFile(const fs::path& file, const std::string& text) {
        writeText(file.string() + ".new", text);
        fs::rename(file.string() + ".new", file);
    }

    DisplayImage renderHeadless(const std::vector<std::string>& extra, const std::string& name) {
        std::vector<std::string> args = {"render", scene.string(), "--size", kSize, "-o", name};
        args.insert(args.end(), extra.begin(), extra.end());
        RunResult r = runRaylab(args, env, dir.path());
        EXPECT_EQ(r.status, 0) << r.err;
        return picture(name);
    }
};

}  // namespace

TEST_F(ReloadTest, ReplacingAnExerciseFileChangesThePicture) {
    auto view = startView("wait 1\nscreenshot before.png\nwait-reload 60\nwait 1\nscreenshot after.png\nquit\n");
    ASSERT_TRUE(waitForFile(dir / "before.png", kStart));
    // Save by writing a new file and renaming it over the old one (new inode),
    // as vim and many IDEs do: the stub of exercise 3 instead of the solution.
    fs::copy(exercisesDir() / "03-lambert.glsl", impl / "03-lambert.glsl.new");
    fs::rename(impl / "03-lambert.glsl.new", impl / "03-lambert.glsl");
    RunResult r = view->wait(kFinish);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("reloaded"), std::string::npos) << r.out;

    DisplayImage before = picture("before.png"), after = picture("after.png");
    EXPECT_GT(comparePictures(before, after).offFraction, 0.05) << "the edit must show";
    DisplayImage expected = renderHeadless({"--impl", impl.string()}, "expected.png");
    EXPECT_LE(comparePictures(after, expected).offFraction, kMaxOffFraction);
}

TEST_F(ReloadTest, BrokenShaderKeepsTheLastPictureAndShowsTheError) {
    auto view = startView(
        "wait 1\nscreenshot before.png\n"
        "wait-reload 60\nwait 1\nscreenshot broken.png\nscreenshot broken-ui.png ui\n"
        "wait-reload 60\nwait 1\nscreenshot fixed.png\nquit\n",
        {"--no-panel"});
    const fs::path file = impl / "05-ggx.glsl";
    const std::string original = readText(file);
    const long lines = std::count(original.begin(), original.end(), '\n');
    ASSERT_TRUE(waitForFile(dir / "before.png", kStart));
    replaceFile(file, original + "\nthis is not GLSL\n");
    ASSERT_TRUE(waitForFile(dir / "broken-ui.png", kStart));
    replaceFile(file, original);
    RunResult r = view->wait(kFinish);
    ASSERT_EQ(r.status, 0) << "fixed before the end, so no error is left: " << r.err;

    // The terminal: file:line: error, at the line that was added.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex("05-ggx\\.glsl:([0-9]+): error")))
        << "stderr must name file:line:\n"
        << r.err;
    EXPECT_EQ(std::stol(m[1]), lines + 2) << r.err;
    EXPECT_NE(r.err.find("this is not GLSL"), std::string::npos) << "the source line is shown:\n" << r.err;

    // The picture: unchanged while broken, and again after the fix.
    DisplayImage before = picture("before.png");
    EXPECT_EQ(comparePictures(picture("broken.png"), before).maxLsb, 0);
    EXPECT_EQ(comparePictures(picture("fixed.png"), before).maxLsb, 0);
    // The screen: the error box (light red text) over the picture.
    DisplayImage ui = picture("broken-ui.png");
    long red = 0;
    for (int y = 0; y < ui.height; ++y)
        for (int x = 0; x < ui.width; ++x) {
            const std::uint8_t* p = ui.at(x, y);
            const std::uint8_t* q = before.at(x, y);
            if (p[0] > 200 && p[1] < 160 && p[2] < 160 && (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])) ++red;
        }
    EXPECT_GT(red, 50) << "the error is drawn on screen";
}

TEST_F(ReloadTest, SceneFileReloadsAndABrokenOneKeepsTheLastScene) {
    auto view = startView(
        "wait 1\nscreenshot before.png\n"
        "wait-reload 60\nwait 1\nscreenshot edited.png\n"
        "wait-reload 60\nwait 1\nscreenshot broken.png\nquit\n");
    ASSERT_TRUE(waitForFile(dir / "before.png", kStart));
    Scene edited = loadSceneFile(scene.string()).scene;
    edited.spheres[0].material.albedo = {0.1, 0.5, 0.9};  // the floor turns blue
    saveSceneFile(edited, scene.string() + ".new");
    fs::rename(scene.string() + ".new", scene);
    ASSERT_TRUE(waitForFile(dir / "edited.png", kStart));
    DisplayImage expected = renderHeadless({}, "expected.png");  // the edited file, before it breaks
    replaceFile(scene, "{ \"camera\": ");
    RunResult r = view->wait(kFinish);
    EXPECT_EQ(r.status, 1) << "a run that ends with an error on screen fails";
    EXPECT_NE(r.err.find("scene.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("last good scene"), std::string::npos) << r.err;

    EXPECT_GT(comparePictures(picture("before.png"), picture("edited.png")).offFraction, 0.2);
    EXPECT_LE(comparePictures(picture("edited.png"), expected).offFraction, kMaxOffFraction);
    EXPECT_EQ(comparePictures(picture("broken.png"), picture("edited.png")).maxLsb, 0);
}

TEST_F(ReloadTest, CtrlSSavesTheSceneWithTheTrackballCamera) {
    // The save writes a new file beside the scene (SCENE-edited.json): the
    // course file itself is never the default target.
    auto view = startView("drag 50 40 100 80\nkey Ctrl+S\nwait 1\nquit\n");
    RunResult r = view->wait(kFinish);
    ASSERT_EQ(r.status, 0) << r.err;

    Scene original = loadSceneFile((sourceRoot() / "scenes" / "lecture.json").string()).scene;
    Trackball predicted(original.camera, 160, 120);
    predicted.beginDrag({50, 40}, Trackball::Mode::Rotate);
    predicted.drag({100, 80});
    predicted.endDrag();
    const Camera expected = predicted.camera();
    EXPECT_EQ(loadSceneFile(scene.string()).scene.camera.position, original.camera.position) << "untouched";
    Scene saved = loadSceneFile((scene.parent_path() / "scene-edited.json").string()).scene;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(saved.camera.position[i], expected.position[i], 1e-9);
        EXPECT_NEAR(saved.camera.target[i], expected.target[i], 1e-9);
    }
    EXPECT_EQ(saved.spheres.size(), original.spheres.size());
}

// The moving picture's program is specialised to the scene's structure only
// (Purpose::LiveView, render/define_table.h): a value edit never builds
// another one, a structural edit does. The still picture's program has the
// values compiled in too (Purpose::LiveStill): a value edit builds that one
// again (docs/decisions.md, "One program").
TEST_F(ReloadTest, ValueEditsNeverRecompileAStructuralEditDoes) {
    auto view = startView(
        "wait 1\nscreenshot before.png\n"
        "wait-reload 60\nwait 1\nscreenshot values.png\n"
        "wait-reload 60\nwait 1\nscreenshot structure.png\nquit\n");
    ASSERT_TRUE(waitForFile(dir / "before.png", kStart));
    Scene edited = loadSceneFile(scene.string()).scene;
    for (Sphere& s : edited.spheres) {
        s.material.metallic = 0.0;
        s.material.roughness = 0.5 * s.material.roughness + 0.1;
    }
    edited.render.exposure = 1.7;
    edited.lights[0].position.x += 0.5;
    saveSceneFile(edited, scene.string() + ".new");
    fs::rename(scene.string() + ".new", scene);
    ASSERT_TRUE(waitForFile(dir / "values.png", kStart));
    DisplayImage valuesExpected = renderHeadless({}, "values-expected.png");
    Sphere extra = edited.spheres[2];
    extra.center.x += 0.3;
    extra.center.z += 1.0;
    extra.radius = 0.2;
    edited.spheres.push_back(extra);  // one more sphere: another program
    edited.render.maxBounces = 3;     // and another bounce limit, in the same edit
    saveSceneFile(edited, scene.string() + ".new");
    fs::rename(scene.string() + ".new", scene);
    RunResult r = view->wait(kFinish);
    ASSERT_EQ(r.status, 0) << r.err;
    DisplayImage structureExpected = renderHeadless({}, "structure-expected.png");

    // The still picture is drawn by the program `raylab render` uses, built
    // for whatever files are shown.
    EXPECT_NE(r.out.find("for the still picture, the scene's numbers compiled in"), std::string::npos) << r.out;
    // Between the two screenshots (the value edit) no structure's program is
    // built, only the still picture's; after them the structural edit builds
    // the structure's program ("raylab: built impl for final ...").
    auto builtLines = [&](std::size_t from, std::size_t to, bool still) {
        std::size_t built = 0;
        for (std::size_t at = r.out.find("raylab: built ", from); at != std::string::npos && at < to;
             at = r.out.find("raylab: built ", at + 1)) {
            const std::size_t end = r.out.find('\n', at);
            if ((r.out.substr(at, end - at).find("for the still picture") != std::string::npos) == still) ++built;
        }
        return built;
    };
    const std::size_t beforeShot = r.out.find("before.png"), valuesShot = r.out.find("values.png");
    ASSERT_NE(beforeShot, std::string::npos) << r.out;
    ASSERT_NE(valuesShot, std::string::npos) << r.out;
    EXPECT_EQ(builtLines(beforeShot, valuesShot, false), 0u) << r.out;
    EXPECT_EQ(builtLines(beforeShot, valuesShot, true), 1u) << r.out;
    EXPECT_GE(builtLines(valuesShot, std::string::npos, false), 1u) << r.out;
    EXPECT_LE(comparePictures(picture("values.png"), valuesExpected).offFraction, kMaxOffFraction);
    EXPECT_LE(comparePictures(picture("structure.png"), structureExpected).offFraction, kMaxOffFraction);
    EXPECT_GT(comparePictures(picture("values.png"), picture("structure.png")).offFraction, 0.001);
}
