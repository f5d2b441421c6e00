// The parts of the live view that need no window: the file watcher, the
// script parser, the key table, adaptive resolution, implementation folders
// and the preset scenes.
#include "window/view_harness.h"

#include "core/error.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "view/adaptive_resolution.h"
#include "view/file_watcher.h"
#include "view/implementation_folder.h"
#include "view/input_script.h"
#include "view/key_bindings.h"
#include "view/presets.h"

#include <gtest/gtest.h>

#include <set>
#include <thread>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;

namespace {
// The live view promises a reload within half a second; the watcher alone
// must report well inside that.
constexpr auto kWatcherBudget = std::chrono::milliseconds(400);

bool changeWithin(FileWatcher& watcher, std::chrono::milliseconds budget) {
    const auto deadline = std::chrono::steady_clock::now() + budget;
    while (std::chrono::steady_clock::now() < deadline) {
        if (watcher.takeChange()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}
}  // namespace

TEST(FileWatcher, ReportsInPlaceEditsReplacementsAndDeletions) {
    TempDir dir;
    const fs::path file = dir / "a.glsl";
    writeText(file, "one");
    FileWatcher watcher;
    watcher.watch({file});
    EXPECT_FALSE(changeWithin(watcher, std::chrono::milliseconds(200))) << "nothing changed yet";

    writeText(file, "two, longer");  // in place
    EXPECT_TRUE(changeWithin(watcher, kWatcherBudget));
    EXPECT_FALSE(watcher.takeChange()) << "reported once";

    writeText(dir / "a.glsl.tmp", "three");  // same size as before? no: a new inode is enough
    fs::rename(dir / "a.glsl.tmp", file);
    EXPECT_TRUE(changeWithin(watcher, kWatcherBudget));

    fs::remove(file);
    EXPECT_TRUE(changeWithin(watcher, kWatcherBudget));
    writeText(file, "back");
    EXPECT_TRUE(changeWithin(watcher, kWatcherBudget)) << "a file that comes back counts";
}

TEST(FileWatcher, SameSizeReplacementIsSeenThroughTheInode) {
    TempDir dir;
    const fs::path file = dir / "a.glsl";
    writeText(file, "abc");
    fs::last_write_time(file, fs::file_time_type::clock::now() - std::chrono::hours(1));
    const auto stamp = fs::last_write_time(file);
    FileWatcher watcher;
    watcher.watch({file});
    writeText(dir / "b.glsl", "xyz");
    fs::last_write_time(dir / "b.glsl", stamp);  // same size, same time: only the inode differs
    fs::rename(dir / "b.glsl", file);
    EXPECT_TRUE(changeWithin(watcher, kWatcherBudget));
}

TEST(InputScript, ParsesEveryCommand) {
    auto script = parseScriptText(
        "# a demo\n"
        "wait 3\nsleep 0.5\nwait-reload 5\n"
        "drag 80 60 120 60 right 8  # pan\n"
        "drag 1 2 3 4\nscroll -2\nkey Ctrl+S\nview bounce2\ndivider 0.3\nresize 320 240\n"
        "screenshot a.png\nscreenshot b.png ui\nquit\n",
        "demo.txt");
    using K = ScriptCommand::Kind;
    ASSERT_EQ(script.size(), 13u);
    EXPECT_EQ(script[0].kind, K::Wait);
    EXPECT_EQ(script[0].count, 3);
    EXPECT_EQ(script[0].line, 2);
    EXPECT_DOUBLE_EQ(script[1].seconds, 0.5);
    EXPECT_EQ(script[2].kind, K::WaitReload);
    EXPECT_EQ(script[3].button, 1);
    EXPECT_EQ(script[3].count, 8);
    EXPECT_EQ(script[3].to, glm::dvec2(120, 60));
    EXPECT_EQ(script[4].button, 0);
    EXPECT_GT(script[4].count, 0) << "a default number of steps";
    EXPECT_DOUBLE_EQ(script[5].value, -2);
    EXPECT_EQ(script[6].text, "Ctrl+S");
    EXPECT_EQ(script[7].text, "bounce2");
    EXPECT_EQ(script[9].to, glm::dvec2(320, 240));
    EXPECT_FALSE(script[10].withUi);
    EXPECT_TRUE(script[11].withUi);
    EXPECT_EQ(script[12].kind, K::Quit);
}

TEST(InputScript, ErrorsNameFileAndLine) {
    auto message = [](const std::string& text) {
        try {
            parseScriptText(text, "s.txt");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("wait 1\ndrag 1 2 3\n"), "s.txt:2: expected Y1, got ''");
    EXPECT_EQ(message("wait -1\n"), "s.txt:1: a frame count must be a whole number >= 0");
    EXPECT_EQ(message("divider 2\n"), "s.txt:1: divider must be between 0 and 1");
    EXPECT_EQ(message("quit now\n"), "s.txt:1: unexpected 'now' at the end of the line");
    EXPECT_EQ(message("drag 1 2 3 4 sideways\n"), "s.txt:1: drag button must be left, right or middle, not 'sideways'");
}

TEST(KeyBindings, EveryKeyIsDocumentedUniqueAndNamedForScripts) {
    std::set<std::pair<int, bool>> seen;
    for (const KeyBinding& b : keyBindings()) {
        EXPECT_TRUE(seen.insert({b.key, b.ctrl}).second) << b.keys << " is bound twice";
        EXPECT_STRNE(b.what, "") << b.keys;
        EXPECT_EQ(bindingByName(b.keys).action, b.action) << b.keys;
    }
    for (int v = 0; v <= 9; ++v) {
        auto b = bindingByName(std::to_string(v));
        EXPECT_EQ(b.action, Action::SetView);
        EXPECT_EQ(b.argument, v);
    }
    EXPECT_THROW(bindingByName("Hyper+Q"), Error);
}

TEST(AdaptiveResolution, ShrinksOnlyWhileMovingAndOnlyWhenSlow) {
    AdaptiveResolution a;
    EXPECT_EQ(a.scale(true, 640, 480), 1.0) << "nothing measured yet";
    const double pixels = 640.0 * 480.0;
    a.record(AdaptiveResolution::kMovingBudgetMs * 4, pixels);  // the full frame costs 4 budgets
    EXPECT_EQ(a.scale(false, 640, 480), 1.0) << "standing still: full resolution";
    EXPECT_DOUBLE_EQ(a.scale(true, 640, 480), 0.5) << "half the width and height: a quarter of the cost";
    a.enabled = false;
    EXPECT_EQ(a.scale(true, 640, 480), 1.0);
    AdaptiveResolution slow;
    slow.record(AdaptiveResolution::kMovingBudgetMs * 1000, pixels);
    EXPECT_DOUBLE_EQ(slow.scale(true, 640, 480), AdaptiveResolution::kMinRows / 480.0) << "as low as needed";
    // 1080p on llvmpipe (2.7 s a frame, the figure): below the old
    // quarter-width floor, at the budget: (s^2 * 2700 ms) <= 33 ms.
    AdaptiveResolution llvmpipe;
    llvmpipe.record(2700, 1920.0 * 1080.0);
    const double s = llvmpipe.scale(true, 1920, 1080);
    EXPECT_LT(s, 0.25);
    EXPECT_LE(s * s * 2700, AdaptiveResolution::kMovingBudgetMs);
    EXPECT_GT(s * s * 2700 * 2, AdaptiveResolution::kMovingBudgetMs * 0.99) << "one step more would have fitted";
    AdaptiveResolution fast;
    fast.record(AdaptiveResolution::kMovingBudgetMs / 2, pixels);
    EXPECT_EQ(fast.scale(true, 640, 480), 1.0) << "fast enough: never drops";
}

TEST(ImplementationFolder, PartialFolderTakesTheRestFromSolutions) {
    TempDir dir;
    fs::copy(exercisesDir() / "05-ggx.glsl", dir / "05-ggx.glsl");
    Implementation impl = implementationFrom(dir.path(), "--compare");
    EXPECT_EQ(impl.dir, solutionsDir());
    ASSERT_EQ(impl.overrides.size(), 1u);
    EXPECT_EQ(impl.fileFor("05-ggx.glsl"), dir / "05-ggx.glsl");
    EXPECT_EQ(implementationFrom(exercisesDir(), "--impl").dir, exercisesDir());
    fs::create_directories(dir / "empty");
    EXPECT_THROW(implementationFrom(dir / "empty", "--compare"), Error);
    EXPECT_THROW(implementationFrom(dir / "missing", "--compare"), Error);
}

TEST(ImplementationFolder, AMutantFileReplacesItsExercise) {
    TempDir dir;
    const fs::path mutant = dir / "05-ggx--missing-pi.glsl";
    writeText(mutant, "// a mutant\n");
    Implementation impl = implementationFrom(mutant, "--compare");
    EXPECT_EQ(impl.dir, solutionsDir());
    EXPECT_EQ(impl.fileFor("05-ggx.glsl"), mutant);
    EXPECT_EQ(impl.fileFor("06-geometry.glsl"), solutionsDir() / "06-geometry.glsl");
    EXPECT_NE(implementationLabel(impl).find("05-ggx--missing-pi.glsl"), std::string::npos)
        << implementationLabel(impl);
    writeText(dir / "notes.glsl", "");
    EXPECT_THROW(implementationFrom(dir / "notes.glsl", "--compare"), Error);
}

TEST(Presets, EveryPresetSceneLoadsCleanly) {
    auto presets = presetScenes();
    ASSERT_GE(presets.size(), 8u) << "the course figures in scenes/presets/";
    for (const auto& file : presets) {
        LoadedScene loaded = loadSceneFile(file.string());
        EXPECT_TRUE(loaded.warnings.empty()) << file << ": " << loaded.warnings.front();
        EXPECT_FALSE(presetTitle(file).empty());
    }
    EXPECT_EQ(presetTitle("scenes/presets/01-roughness-0-to-1.json"), "roughness 0 to 1");
}

// docs/lecture.md lists every key and mouse action of the table.
TEST(KeyBindings, TheLectureGuideListsEveryKeyAndMouseAction) {
    const std::string guide = readText(sourceRoot() / "docs" / "lecture.md");
    ASSERT_FALSE(guide.empty());
    for (const KeyBinding& b : keyBindings())
        EXPECT_NE(guide.find("`" + std::string(b.keys) + "`"), std::string::npos) << b.keys << " is not in docs/lecture.md";
    for (const MouseBinding& m : mouseBindings())
        EXPECT_NE(guide.find("| " + std::string(m.input) + " |"), std::string::npos) << m.input;
}
