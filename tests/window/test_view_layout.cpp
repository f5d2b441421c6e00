// The projector layout (issue 26): at UI scales 1, 2 and 3 on 1280x720 and
// 1920x1080, in every state a lecture shows (the wipe with its caption, an
// asked pixel, side by side, a shader error and a scene-file error), no
// widget overlaps another, none leaves the window or is cut by its frame,
// and the caption, the errors and the names leave the spheres visible. The
// window itself reports its rectangles (`layout FILE`, view/layout_report.h);
// the rules are layoutProblems(), checked here on the report and on a few
// hand-made layouts.
//
// RAYLAB_UPDATE_DOC_IMAGES=1 (tests/window/update-layout-images.sh) copies
// the screenshots docs/lecture.md shows to docs/images/lecture/.
#include "window/view_harness.h"

#include "core/error.h"
#include "core/paths.h"
#include "view/layout_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>
#include <memory>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;

namespace {

using K = LayoutBox::Kind;

// ---- the rules, on hand-made layouts ------------------------------------------------------

LayoutReport window720() { return LayoutReport{1280, 720, 1, {}}; }

TEST(LayoutRules, OverlappingWidgetsAreReported) {
    LayoutReport r = window720();
    r.add("caption", K::Widget, {800, 600, 1270, 710});
    r.add("errors", K::Widget, {400, 650, 900, 710});
    const auto problems = layoutProblems(r);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("caption overlaps errors"), std::string::npos) << problems[0];
}

TEST(LayoutRules, AWidgetOverASphereIsReportedTheDividerAndThePanelAreNot) {
    LayoutReport r = window720();
    r.add("sphere 1", K::Subject, {300, 270, 450, 420});
    r.add("caption", K::Widget, {400, 400, 1270, 710});
    r.add("divider", K::Line, {639, 0, 641, 720});
    r.add("panel", K::Tool, {10, 10, 350, 710});
    r.add("sphere 2", K::Subject, {600, 100, 750, 250});  // under the divider: that is the wipe's job
    const auto problems = layoutProblems(r);
    ASSERT_EQ(problems.size(), 2u);  // the caption over sphere 1; the divider crossing the caption
    EXPECT_NE(problems[0].find("overlaps"), std::string::npos);
    for (const std::string& p : problems) EXPECT_EQ(p.find("panel"), std::string::npos) << p;
}

TEST(LayoutRules, LeavingTheWindowAndACutTextAreReportedScrolledRowsAreNot) {
    LayoutReport r = window720();
    r.add("panel", K::Tool, {30, 30, 606, 690});
    r.add("view dropdown", K::Part, {54, 693, 560, 750}, "panel");  // scrolled below the panel's height
    r.add("view name", K::Part, {66, 702, 1054, 741}, "view dropdown");  // wider than its frame
    r.add("toast", K::Widget, {1100, 10, 1290, 40});
    const auto problems = layoutProblems(r);
    ASSERT_EQ(problems.size(), 2u) << problems.size();
    EXPECT_NE(problems[0].find("view name is cut by view dropdown"), std::string::npos) << problems[0];
    EXPECT_NE(problems[1].find("toast leaves the window"), std::string::npos) << problems[1];
}

// The help (issue 37): a cover hides the caption and the spheres under it
// (no overlap), but not the panel; its rows never scroll, so a row below
// its bottom is cut, not scrolled away.
TEST(LayoutRules, TheHelpCoversWidgetsNotThePanelAndItsRowsAreWhole) {
    LayoutReport r = window720();
    r.add("caption", K::Widget, {800, 600, 1270, 710});
    r.add("sphere 1", K::Subject, {300, 270, 450, 420});
    r.add("help", K::Cover, {10, 10, 1270, 710});
    r.add("help rows", K::Part, {20, 40, 1260, 700}, "help");
    EXPECT_TRUE(layoutProblems(r).empty()) << layoutProblems(r).front();
    r.add("help rows", K::Part, {20, 40, 1260, 730}, "help");  // a row below the help's bottom
    r.add("panel", K::Tool, {10, 10, 350, 710});
    const auto problems = layoutProblems(r);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].find("help rows is cut by help"), std::string::npos) << problems[0];
    EXPECT_NE(problems[1].find("help overlaps panel"), std::string::npos) << problems[1];
    EXPECT_EQ(parseLayoutJson(layoutJson(r), "layout.json").boxes[2].kind, K::Cover);
}

// The docked panel (issue 37): opaque, so it must leave the picture area
// and every sphere the camera frames visible (at 720p, UI scale 3 it hid
// two of five); the caption over the picture is its overlay, no problem.
TEST(LayoutRules, TheDockedPanelCoversNeitherThePictureNorASphere) {
    LayoutReport r = window720();
    r.add("picture", K::Picture, {636, 0, 1280, 720});
    r.add("panel", K::Dock, {30, 30, 606, 690});
    r.add("sphere 1", K::Subject, {800, 300, 880, 380});
    r.add("caption", K::Widget, {640, 480, 1270, 700});
    EXPECT_TRUE(layoutProblems(r).empty()) << layoutProblems(r).front();
    r.boxes[0].rect.x0 = 0;  // the picture under the panel, as before
    r.add("sphere 2", K::Subject, {500, 300, 580, 380});
    const auto problems = layoutProblems(r);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_NE(problems[0].find("panel covers picture"), std::string::npos) << problems[0];
    EXPECT_NE(problems[1].find("panel covers sphere 2"), std::string::npos) << problems[1];
    EXPECT_EQ(parseLayoutJson(layoutJson(r), "layout.json").boxes[1].kind, K::Dock);
}

TEST(LayoutRules, TheReportSurvivesItsJson) {
    LayoutReport r = window720();
    r.uiScale = 2;
    r.add("panel", K::Tool, {30, 30, 606, 690});
    r.add("asked pixel", K::Part, {40, 300, 590, 500}, "panel");
    const LayoutReport back = parseLayoutJson(layoutJson(r), "layout.json");
    ASSERT_EQ(back.boxes.size(), 2u);
    EXPECT_EQ(back.width, 1280);
    EXPECT_FLOAT_EQ(back.uiScale, 2);
    EXPECT_EQ(back.boxes[1].kind, K::Part);
    EXPECT_EQ(back.boxes[1].parent, "panel");
    EXPECT_FLOAT_EQ(back.boxes[1].rect.y1, 500);
    EXPECT_THROW(parseLayoutJson("{\"width\": 3}", "bad.json"), Error);
}

// ---- the window (Xvfb) ---------------------------------------------------------------------

// Generous: two shared cores, a 1080p frame of llvmpipe; a passing run of
// one size takes seconds.
constexpr auto kStart = std::chrono::seconds(120);
constexpr auto kFinish = std::chrono::seconds(240);

const char* const kStates[] = {"wipe", "pick", "side", "errors"};

// RAYLAB_LAYOUT_ALL=1: every view at both sizes, and (with
// RAYLAB_UPDATE_DOC_IMAGES=1) every screenshot into docs/lecture.md's gallery.
bool allLayouts() {
    const char* all = std::getenv("RAYLAB_LAYOUT_ALL");
    return all && std::string(all) == "1";
}


int count(const LayoutReport& r, const std::string& prefix) {
    int n = 0;
    for (const LayoutBox& b : r.boxes) n += b.name.rfind(prefix, 0) == 0;
    return n;
}

const LayoutBox* find(const LayoutReport& r, const std::string& name) {
    for (const LayoutBox& b : r.boxes)
        if (b.name == name) return &b;
    return nullptr;
}

// A point of the picture, in window pixels, given as a fraction of the
// whole window's picture (as it was before the panel docked): the picture
// is right of the panel (its right edge plus a margin, as panelRect() and
// the window put it) and shows the whole window's width of the scene, so a
// sphere keeps its place across the picture's width and moves towards the
// middle vertically by the picture's width over the window's.
int pictureX(int w, int s, double fx) {
    const double offset = std::round(10.0 * s + std::min(340.0 * s, 0.45 * w) + 10.0 * s);
    return int(offset + fx * (w - offset));
}
int pictureY(int w, int h, int s, double fy) {
    const double offset = std::round(10.0 * s + std::min(340.0 * s, 0.45 * w) + 10.0 * s);
    return int(0.5 * h + (fy - 0.5) * h * (w - offset) / w);
}

// One window a size (the scales and states are script steps: one start-up,
// one shader compile), the lecture scene against itself in Blinn-Phong
// (--compare-model: a wipe and side by side without a second folder), the
// F view whose caption speaks of the spheres' highlights.
void checkSize(int w, int h) {
    Xvfb x(w, h);
    const auto env = windowEnv(x);
    TempDir dir;
    const fs::path impl = dir / "impl", scene = dir / "lecture.json";
    fs::create_directories(impl);
    for (const auto& entry : fs::directory_iterator(solutionsDir())) fs::copy(entry.path(), impl / entry.path().filename());
    fs::copy(sourceRoot() / "scenes" / "lecture.json", scene);
    const std::string size = std::to_string(w) + "x" + std::to_string(h);

    auto shot = [](const std::string& name) {
        return "wait 2\nscreenshot " + name + ".png ui\nlayout " + name + ".json\n";
    };
    // Ordered so the picture renders seldom (a 1080p frame is the cost):
    // a new UI scale moves only the widgets, except side by side, where the
    // pictures sit right of the panel.
    std::string script = "view f\nwait 1\n";
    for (int s : {1, 2, 3}) {
        const std::string tag = "-" + std::to_string(s);
        script += "ui-scale " + std::to_string(s) + "\n" + shot(std::string("wipe") + tag);
        // The white sphere, right of the divider.
        script += "pick " + std::to_string(pictureX(w, s, 0.70)) + " " + std::to_string(pictureY(w, h, s, 0.48)) + "\n" +
                  shot(std::string("pick") + tag);
    }
    script += "key P\n" + shot("toast");  // "saved raylab-....png" for 3 s, at UI scale 3
    script += "key X\n";
    for (int s : {1, 2, 3}) script += "ui-scale " + std::to_string(s) + "\n" + shot("side-" + std::to_string(s));
    script += "key X\n";
    // Errors: the test breaks the shader, then the scene file, between these steps.
    script += "screenshot ready-shader.png\nwait-reload 60\nscreenshot ready-scene.png\nwait-reload 60\n";
    for (int s : {1, 2, 3}) script += "ui-scale " + std::to_string(s) + "\n" + shot("errors-" + std::to_string(s));
    script += "quit\n";
    writeText(dir / "script.txt", script);

    Process view({RAYLAB_BINARY, "view", scene.string(), "--impl", impl.string(), "--compare-model", "blinn-phong",
                  "--size", size, "--script", "script.txt"},
                 env, dir.path());
    auto replaceFile = [](const fs::path& file, const std::string& text) {  // one step, as an editor saves
        writeText(file.string() + ".new", text);
        fs::rename(file.string() + ".new", file);
    };
    ASSERT_TRUE(waitForFile(dir / "ready-shader.png", kStart)) << size;
    replaceFile(impl / "05-ggx.glsl", readText(impl / "05-ggx.glsl") + "\nthis is not GLSL\n");
    ASSERT_TRUE(waitForFile(dir / "ready-scene.png", kStart)) << size;
    replaceFile(scene, "{ \"camera\": \n");
    const RunResult r = view.wait(kFinish);
    // 1: the run ends with the errors on screen, as they were left.
    ASSERT_EQ(r.status, 1) << size << ": " << r.err;
    ASSERT_NE(r.err.find("the run ended with an error on screen"), std::string::npos) << r.err;

    for (int s : {1, 2, 3})
        for (const char* state : kStates) {
            const std::string name = std::string(state) + "-" + std::to_string(s);
            const std::string what = size + " at UI scale " + std::to_string(s) + ", " + state;
            const LayoutReport report = parseLayoutJson(readText(dir / (name + ".json")), name + ".json");
            EXPECT_EQ(report.width, w) << what;
            EXPECT_FLOAT_EQ(report.uiScale, float(s)) << what;
            for (const std::string& p : layoutProblems(report)) ADD_FAILURE() << what << ": " << p;
            // Every element of the state is in the report: a rule cannot pass on a box left out.
            const std::string st = state;
            EXPECT_NE(find(report, "panel"), nullptr) << what;
            // The caption, except where an error needs its room (errors first).
            if (st != "errors") EXPECT_NE(find(report, "caption"), nullptr) << what;
            EXPECT_GE(count(report, "sphere "), st == "side" ? 10 : 5) << what << ": the spheres, not the ground";
            EXPECT_EQ(count(report, "divider") > 0, st != "side") << what;
            EXPECT_EQ(find(report, "wipe left name") != nullptr, st != "side") << what;
            EXPECT_EQ(find(report, "left name") != nullptr, st == "side") << what;
            EXPECT_EQ(find(report, "asked pixel") != nullptr, st != "wipe" || s > 1) << what << ": asked at scale 1";
            EXPECT_EQ(find(report, "errors") != nullptr, st == "errors") << what;
            // The report is where the window drew: the caption's colour bar
            // runs from black to white across its rectangle.
            const DisplayImage image = readPng((dir / (name + ".png")).string());
            ASSERT_EQ(image.width, w) << what;
            if (const LayoutBox* bar = find(report, "colour bar")) {
                const LayoutRect& b = bar->rect;
                const int y = int(0.5f * (b.y0 + b.y1));
                EXPECT_LT(image.at(int(b.x0 + 0.05f * (b.x1 - b.x0)), y)[0], 40) << what << ": the bar's dark end";
                EXPECT_GT(image.at(int(b.x0 + 0.95f * (b.x1 - b.x0)), y)[0], 215) << what << ": the bar's light end";
            }
        }
    {  // The toast of a screenshot taken with P: clear of the overlays, inside the window.
        const LayoutReport report = parseLayoutJson(readText(dir / "toast.json"), "toast.json");
        EXPECT_NE(find(report, "toast"), nullptr) << size << ": P shows a toast";
        for (const std::string& p : layoutProblems(report)) ADD_FAILURE() << size << " at UI scale 3, toast: " << p;
    }
    // The six main screenshots (an asked pixel over the wipe, the caption,
    // the panel) and the errors at the tightest setting.
    for (int s : {1, 2, 3})
        maybeUpdateDocImage(dir / ("pick-" + std::to_string(s) + ".png"),
                            "layout-" + std::to_string(h) + "p-scale-" + std::to_string(s) + ".png");
    if (allLayouts())  // the gallery of docs/lecture.md, "Every view at every scale"
        for (int s : {1, 2, 3})
            for (const char* state : kStates)
                maybeUpdateDocImage(dir / (std::string(state) + "-" + std::to_string(s) + ".png"),
                                    "every-view/" + std::to_string(h) + "p-" + state + "-" + std::to_string(s) + ".png");
    if (h == 720) maybeUpdateDocImage(dir / "errors-3.png", "layout-720p-scale-3-errors.png");
}

// Every teaching view (its name in the dropdown), the help and an asked
// pixel, on the environment scene, at UI scales 1, 2 and 3 (issue 37): no
// overlap, no cut text, by the window's own report. The views: a few in
// the suite (each a first draw on llvmpipe), all of them with
// RAYLAB_LAYOUT_ALL=1; RAYLAB_UPDATE_DOC_IMAGES=1 copies the help and the
// environment views docs/lecture.md shows.
void checkViews(int w, int h, const std::vector<std::string>& views) {
    Xvfb x(w, h);
    const auto env = windowEnv(x);
    TempDir dir;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    auto shot = [](const std::string& name) { return "wait 2\nscreenshot " + name + ".png ui\nlayout " + name + ".json\n"; };
    std::string script = "wait 1\n";
    std::vector<std::string> states;
    for (int s : {1, 2, 3}) {
        const std::string tag = "-" + std::to_string(s);
        script += "ui-scale " + std::to_string(s) + "\n";
        for (const std::string& v : views) {
            script += "view " + v + "\n" + shot(v + tag);
            states.push_back(v + tag);
        }
        script += "key H\n" + shot("help" + tag) + "key Escape\n";
        states.push_back("help" + tag);
        script += "pick " + std::to_string(pictureX(w, s, 0.62)) + " " + std::to_string(pictureY(w, h, s, 0.55)) + "\n" +
                  shot("pick" + tag);
        states.push_back("pick" + tag);
    }
    script += "quit\n";
    writeText(dir / "script.txt", script);
    const RunResult r = runRaylab({"view", (sourceRoot() / "scenes" / "presets" / "10-environment-on.json").string(),
                                   "--size", size, "--script", "script.txt"},
                                  env, dir.path(), kFinish);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const std::string& state : states) {
        const std::string what = size + ", " + state;
        const LayoutReport report = parseLayoutJson(readText(dir / (state + ".json")), state + ".json");
        for (const std::string& p : layoutProblems(report)) ADD_FAILURE() << what << ": " << p;
        const bool help = state.rfind("help", 0) == 0;
        EXPECT_EQ(find(report, "help") != nullptr, help) << what;
        EXPECT_EQ(find(report, "panel") != nullptr, !help) << what << ": the panel steps aside for the help only";
        if (!help) {
            EXPECT_NE(find(report, "view name"), nullptr) << what;
            EXPECT_NE(find(report, "panel rows"), nullptr) << what;
        }
    }
    if (allLayouts())  // the gallery of docs/lecture.md, "Every view at every scale"
        for (const std::string& state : states)
            maybeUpdateDocImage(dir / (state + ".png"), "every-view/" + std::to_string(h) + "p-environment-" + state + ".png");
    if (h == 720) {
        maybeUpdateDocImage(dir / "help-3.png", "help-720p-scale-3.png");
        for (const std::string v : {"irradiance", "env-bias"})  // the suite's two: their names in the dropdown
            maybeUpdateDocImage(dir / (v + "-2.png"), "view-" + v + "-720p-scale-2.png");
    } else {
        maybeUpdateDocImage(dir / "help-2.png", "help-1080p-scale-2.png");
        maybeUpdateDocImage(dir / "pick-3.png", "environment-pick-1080p-scale-3.png");
    }
}

const std::vector<std::string> kAllViews = {"final",  "d",      "g",          "f",           "fnv",
                                            "diffuse", "specular", "ndotl",   "shadow",      "normals",
                                            "bounce1", "irradiance", "prefiltered", "env-scale", "env-bias"};

}  // namespace

// The suite's share: 720p (the tighter size), two environment views;
// RAYLAB_LAYOUT_ALL=1: every view, at 1080p too.
TEST(ProjectorLayout, EveryViewTheHelpAndAnAskedPixelAtEveryScale) {
    checkViews(1280, 720, allLayouts() ? kAllViews : std::vector<std::string>{"irradiance", "env-bias"});
    if (allLayouts()) checkViews(1920, 1080, kAllViews);
}

TEST(ProjectorLayout, NothingOverlapsAt720pOnAnyScale) { checkSize(1280, 720); }

TEST(ProjectorLayout, NothingOverlapsAt1080pOnAnyScale) { checkSize(1920, 1080); }

// The shadow view draws only 0 and 1: its caption's bar is two swatches,
// black then white, with nothing between (a ramp would show greys the view
// never draws; at 40% a ramp is grey 102, which fails the first check).
TEST(ProjectorLayout, TheShadowViewsBarIsTwoSwatches) {
    Xvfb x(640, 360);
    const auto env = windowEnv(x);
    TempDir dir;
    writeText(dir / "script.txt", "view shadow\nwait 1\nscreenshot shadow.png ui\nlayout shadow.json\nquit\n");
    Process view({RAYLAB_BINARY, "view", (sourceRoot() / "scenes" / "lecture.json").string(), "--size", "640x360",
                  "--script", "script.txt"},
                 env, dir.path());
    const RunResult r = view.wait(kFinish);
    ASSERT_EQ(r.status, 0) << r.err;
    const LayoutReport report = parseLayoutJson(readText(dir / "shadow.json"), "shadow.json");
    const LayoutBox* bar = find(report, "colour bar");
    ASSERT_NE(bar, nullptr);
    const DisplayImage image = readPng((dir / "shadow.png").string());
    const LayoutRect& b = bar->rect;
    const int y = int(0.5f * (b.y0 + b.y1));
    for (float f : {0.1f, 0.4f}) EXPECT_LT(image.at(int(b.x0 + f * (b.x1 - b.x0)), y)[0], 20) << "0: shadow, at " << f;
    for (float f : {0.6f, 0.9f}) EXPECT_GT(image.at(int(b.x0 + f * (b.x1 - b.x0)), y)[0], 235) << "1: lit, at " << f;
}
