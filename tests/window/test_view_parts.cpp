// The parts of the live view that need no window: the file watcher, the
// script parser, the key table, adaptive resolution, implementation folders
// and the preset scenes.
#include "window/view_harness.h"

#include "core/error.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/define_table.h"
#include "render/scene_uniforms.h"
#include "view/adaptive_resolution.h"
#include "view/file_watcher.h"
#include "view/implementation_folder.h"
#include "view/input_script.h"
#include "view/key_bindings.h"
#include "view/presets.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <algorithm>
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
    EXPECT_EQ(message("layout\n"), "s.txt:1: layout needs a file name");
    EXPECT_EQ(message("ui-scale 9\n"), "s.txt:1: ui-scale must be between 0.5 and 4");
}

TEST(InputScript, ParsesTheLayoutCommands) {
    auto script = parseScriptText("ui-scale 2.5\nlayout out.json\n", "s.txt");
    ASSERT_EQ(script.size(), 2u);
    EXPECT_EQ(script[0].kind, ScriptCommand::Kind::UiScale);
    EXPECT_DOUBLE_EQ(script[0].value, 2.5);
    EXPECT_EQ(script[1].kind, ScriptCommand::Kind::Layout);
    EXPECT_EQ(script[1].text, "out.json");
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

TEST(AdaptiveResolution, TheOverheadOutsideTheRenderShrinksTheRenderBudget) {
    // 1080p on llvmpipe under load (issue #14): the render alone would fit
    // a quarter width, but upscale + panel + swap take most of the budget.
    const double pixels = 1920.0 * 1080.0;
    AdaptiveResolution a;
    a.record(22 * 16, pixels);  // 22 ms at a quarter of each side: 352 ms at full size
    const double alone = a.scale(true, 1920, 1080);
    EXPECT_GE(alone, 0.25) << "without the overhead, a quarter width looks affordable";
    a.recordFrame(85, 22);  // a whole frame took 85 ms, 63 of them outside the render
    const double s = a.scale(true, 1920, 1080);
    EXPECT_LT(s, 0.25) << "the overhead leaves less for the render: below a quarter";
    EXPECT_NEAR(a.overheadMs(), 63, 1e-9);
    EXPECT_GE(s, AdaptiveResolution::kMinRows / 1080.0);
    a.recordFrame(10, 12);  // a render longer than its frame (timer jitter) is no negative overhead
    EXPECT_GE(a.overheadMs(), 0.0);
}

TEST(LiveDefines, ValuesNeverChangeTheProgramStructureDoes) {
    const Scene lecture = loadSceneFile((scenesDir() / "lecture.json").string()).scene;
    ImplementationFacts started;  // exercise 09 written, nothing else known about the files
    started.traceStarted = true;
    auto defines = [&](const Scene& s, View v = View::Final) {
        return definesFor(s, started, isPictureView(v) ? Purpose::LiveView : Purpose::Generic);
    };
    const ShaderDefines base = defines(lecture);
    EXPECT_EQ(base.at("RL_SPHERE_COUNT"), std::to_string(lecture.spheres.size()));
    EXPECT_EQ(base.at("RL_MAX_BOUNCES"), std::to_string(lecture.render.maxBounces));
    EXPECT_EQ(base.count("RL_PICTURE_ONLY"), 1u);

    // Every value the panel edits: the same program.
    Scene values = lecture;
    for (Sphere& s : values.spheres) {
        s.material.metallic = 0.0;
        s.material.roughness = 0.7;
        s.material.albedo = {0.2, 0.3, 0.4};
        s.material.ao = 0.5;
        s.center += glm::dvec3(0.1, 0.0, 0.0);
    }
    values.lights[1].intensity = 3.0;
    values.lights[0].position.y += 2.0;
    values.render.exposure = 2.5;
    values.render.gamma = 1.8;
    values.render.ambient = 0.2;
    values.camera.position.z += 3.0;
    EXPECT_EQ(defines(values), base);
    EXPECT_NE(definesFor(values, started, Purpose::LiveStill), definesFor(lecture, started, Purpose::LiveStill))
        << "the case must be a hard one: the still picture's program has the values compiled in";

    // Structure: another program.
    Scene more = lecture;
    more.spheres.push_back(lecture.spheres[1]);
    EXPECT_NE(defines(more), base);
    Scene lights = lecture;
    lights.lights.pop_back();
    EXPECT_NE(defines(lights), base);
    Scene bounces = lecture;
    bounces.render.maxBounces = 4;
    EXPECT_NE(defines(bounces), base);
    Scene samples = lecture;  // the panel's four sample counts: a program each, like the bounce limit
    samples.render.spp = 4;
    EXPECT_NE(defines(samples), base);
    Scene beckmann = lecture;
    beckmann.model.distribution = DistributionModel::Beckmann;
    EXPECT_NE(defines(beckmann), base);

    Scene ground = lecture;
    ground.spheres[0].radius = 0.5;  // no huge sphere left: no root to refine (a file edit; the panel has no radius)
    EXPECT_NE(defines(ground), base);

    // The teaching term views use the generic program; the bounce views are pictures.
    EXPECT_EQ(defines(lecture, View::D), modelDefines(lecture.model));
    EXPECT_EQ(defines(lecture, View::Bounce), base);
    EXPECT_EQ(definesFor(lecture, ImplementationFacts{}, Purpose::LiveView), modelDefines(lecture.model))
        << "exercise 09 still the stub: the generic program with its first-hit fallback";
}

// What the files allow reaches the live picture program as it reaches
// `raylab render`'s: the solutions are finished and their 02 is the course's.
TEST(LiveDefines, TheFilesDefinesReachThePictureProgram) {
    const Scene lecture = loadSceneFile((scenesDir() / "lecture.json").string()).scene;
    const ImplementationFacts files = implementationFacts(Implementation{solutionsDir(), {}});
    EXPECT_TRUE(files.exercisesFinished);
    EXPECT_TRUE(files.courseFile("02-intersect.glsl"));
    const ShaderDefines live = definesFor(lecture, files, Purpose::LiveView);
    EXPECT_EQ(live.count("RL_EXERCISES_FINISHED"), 1u);
    EXPECT_EQ(definesFor(lecture, files, Purpose::LiveStill).count("RL_EXERCISES_FINISHED"), 1u);
    EXPECT_EQ(definesFor(lecture, files, Purpose::Picture).count("RL_EXERCISES_FINISHED"), 1u);
    // A student's files that are not finished (exercise 09 written, the rest
    // unknown) get none of it.
    ImplementationFacts started;
    started.traceStarted = true;
    EXPECT_EQ(definesFor(lecture, started, Purpose::LiveStill).count("RL_EXERCISES_FINISHED"), 0u);
    // ...and never to the teaching views' generic program.
    EXPECT_EQ(definesFor(lecture, files, Purpose::Generic), modelDefines(lecture.model));
}

// The command docs/performance.md gives for the live view's program, run as
// written (smaller and shorter: --size, --frames and --warmup appended): one
// table with both programs for the picture and a term view, and the live
// picture equal to the generic one's.
TEST(ViewBench, TheDocumentedCommandComparesBothProgramsInOneRun) {
    const std::string doc = readText(sourceRoot() / "docs" / "performance.md");
    const std::size_t at = doc.find("./raylab bench --sweeps view");
    ASSERT_NE(at, std::string::npos) << "docs/performance.md gives the command";
    std::string command = doc.substr(at, doc.find_first_of("#\n", at) - at);
    while (!command.empty() && command.back() == ' ') command.pop_back();
    const rl::test::CommandResult r =
        rl::test::runShell("cd " + sourceRoot().string() + " && " + command + " --size 96x54 --frames 1 --warmup 1");
    ASSERT_EQ(r.status, 0) << command << "\n" << r.output;
    for (const char* row : {"generic  final", "before   final", "live     final", "generic  d", "live     d", "view final: live",
                            "view d: live"})
        EXPECT_NE(r.output.find(row), std::string::npos) << row << "\n" << r.output;
    // The live picture agrees with the generic one: max LSB (the last column) small.
    const std::size_t live = r.output.find("live     final");
    const std::string line = r.output.substr(live, r.output.find('\n', live) - live);
    const int maxLsb = std::atoi(line.substr(line.find_last_of(' ') + 1).c_str());
    // 1 LSB: the same model in float32; the programs differ only in loop
    // unrolling and folded constants, which may round a value across an
    // 8-bit boundary.
    EXPECT_LE(maxLsb, 1) << line;
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

// Keys by character (issue 37): on a German layout "+" is the key where a US
// "]" is, and "]" is AltGr+9; the character typed decides, not the key's place.
TEST(KeyBindings, PrintableKeysGoByTheCharacterTyped) {
    auto action = [](unsigned c) { return bindingForCharacter(c) ? int(bindingForCharacter(c)->action) : -1; };
    EXPECT_EQ(action('+'), int(Action::UiScaleUp));
    EXPECT_EQ(action('='), int(Action::UiScaleUp));  // "+" is Shift+= on a US layout
    EXPECT_EQ(action('-'), int(Action::UiScaleDown));
    EXPECT_EQ(action(']'), int(Action::BounceUp));
    EXPECT_EQ(action('['), int(Action::BounceDown));
    EXPECT_EQ(action('y'), int(Action::SetView));
    EXPECT_EQ(bindingForCharacter('Y')->argument, 13);
    EXPECT_EQ(bindingForCharacter('9')->argument, 9);
    EXPECT_EQ(action(0xFC), -1);  // u umlaut: no key of the help (its US place is "[")
    // The key callback leaves exactly these to the characters; Ctrl and the
    // named keys (F1, PageDown, Up) go by key.
    for (const KeyBinding& b : keyBindings()) {
        const std::string keys = b.keys;
        EXPECT_EQ(byCharacter(b), keys.size() == 1) << keys;
        if (byCharacter(b)) EXPECT_EQ(bindingForCharacter(unsigned(char(std::tolower(keys[0]))))->action, b.action) << keys;
    }
}

// The docs' view names are the parser's: every name of the --view row in
// docs/lecture.md (issue 37: `bounceK` was documented, `bounce1` accepted).
TEST(ViewNames, EveryDocumentedNameIsAccepted) {
    const std::string guide = readText(sourceRoot() / "docs" / "lecture.md");
    const std::size_t row = guide.find("| `--view NAME` |");
    ASSERT_NE(row, std::string::npos);
    const std::string line = guide.substr(row + 17, guide.find('\n', row) - row - 17);
    int names = 0;
    for (std::size_t a = line.find('`'); a != std::string::npos; a = line.find('`', line.find('`', a + 1) + 1)) {
        const std::string name = line.substr(a + 1, line.find('`', a + 1) - a - 1);
        int bounce = 0;
        EXPECT_NO_THROW(parseView(name, bounce)) << name;
        ++names;
    }
    EXPECT_GE(names, 15);
    int bounce = 0;
    EXPECT_EQ(parseView("bounce1", bounce), View::Bounce);
    EXPECT_EQ(bounce, 1);
}

// PageDown and PageUp step through the course figures of scenes/presets/ in
// their numbered order (issue 37: from lecture.json PageDown opened
// metal-row-reflections.json, the next file of scenes/).
TEST(Presets, PageDownStepsThroughTheCourseFiguresInOrder) {
    const auto presets = presetScenes();
    const int n = presetFigureCount(presets);
    int files = 0;
    for (const auto& e : fs::directory_iterator(sourceRoot() / "scenes" / "presets"))
        files += e.path().extension() == ".json" && e.path().filename().string().find(".cameras.") == std::string::npos;
    EXPECT_EQ(n, files);
    ASSERT_GT(n, 1);
    EXPECT_EQ(presets[0].filename().string().substr(0, 3), "01-");
    for (int i = 0; i < n; ++i) EXPECT_EQ(presets[std::size_t(i)].parent_path().filename(), "presets");
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

// docs/lecture.md's key table (its rows "| `KEY` ...") lists every key and
// mouse action of the table (issue 37: X was named in the text only).
TEST(KeyBindings, TheLectureGuideListsEveryKeyAndMouseAction) {
    const std::string guide = readText(sourceRoot() / "docs" / "lecture.md");
    ASSERT_FALSE(guide.empty());
    std::vector<std::string> rows;  // the first cell of every table row that starts with a key
    std::istringstream lines(guide);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("| `", 0) == 0) rows.push_back(line.substr(0, line.find(" |", 2)));
    for (const KeyBinding& b : keyBindings()) {
        const std::string key = "`" + std::string(b.keys) + "`";
        EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const std::string& r) { return r.find(key) != std::string::npos; }))
            << b.keys << " is not in the key table of docs/lecture.md";
    }
    for (const MouseBinding& m : mouseBindings())
        EXPECT_NE(guide.find("| " + std::string(m.input) + " |"), std::string::npos) << m.input;
}
