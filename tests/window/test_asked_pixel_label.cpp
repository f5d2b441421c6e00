// The asked pixel's answer on the picture (view/asked_pixel_label.h, issue
// 37): with a mutant of an exercise in place, a Ctrl+click (the script's
// `pick`) on a pixel the mistake changes draws a label beside the pixel
// naming that exercise's function with the program's and the model's
// values; the window's layout report has the label inside the window, clear
// of the panel and the other widgets, at UI scales 1 to 3 on small windows:
// 320x240 at scale 1, 640x360 at 2 and 960x540 at 3 leave as little room
// per letter as 1280x720 at scale 4 (the projector's worst case is scale 3).
#include "window/view_harness.h"

#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "render/define_table.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "shader/shader_library.h"
#include "view/asked_pixel_label.h"
#include "view/layout_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

using namespace rl;
using namespace rl::wintest;
using rl::test::readText;
using rl::test::writeText;
namespace fs = std::filesystem;

namespace {

// A copy of solutions/ with one exercise replaced by one of its mutants.
fs::path mutantFolder(const fs::path& root, const std::string& unit, const std::string& mutant) {
    return rl::test::solutionsWithMutant(root, unit + ".glsl", sourceRoot() / "course" / unit / "mutants" / (mutant + ".glsl"));
}

DisplayImage picture(const Implementation& impl, Scene scene, int w, int h) {
    scene.render.width = w;
    scene.render.height = h;
    return renderOnce(buildPictureProgram(impl, definesFor(scene, implementationFacts(impl), Purpose::Picture)), scene,
                      frameFromScene(scene))
        .display;
}

// The pixel the mistake changes most in the right two fifths, from the top
// left: clear of the panel, which takes the left half at every scale of the
// cases (a pick on it is refused: at 640x360, scale 2, its columns are 0 to
// 327, and the sky scene's largest change in the right half lay at 325).
std::pair<int, int> changedPixel(const Implementation& mutant, const Scene& scene, int w, int h) {
    const DisplayImage a = picture(Implementation{sourceRoot() / "solutions", {}}, scene, w, h),
                       b = picture(mutant, scene, w, h);
    int best = 0;
    std::pair<int, int> at{-1, -1};
    for (int y = 0; y < h; ++y)
        for (int x = 3 * w / 5; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
                if (d > best) best = d, at = {x, y};
            }
    return at;
}

const LayoutBox* find(const LayoutReport& r, const std::string& name) {
    for (const LayoutBox& b : r.boxes)
        if (b.name == name) return &b;
    return nullptr;
}

struct LabelCase {
    const char* unit;
    const char* mutant;
    const char* scene;  // "" for the default scene
    int width, height, scale;
    const char* function;  // the function the label names
};

}  // namespace

// The placement rule on its own: beside the pixel where there is room, on
// the other side where the panel or the window's edge is in the way.
TEST(AskedPixelLabelPlacement, BesideThePixelClearOfThePanel) {
    const LayoutRect right = askedPixelLabelBox(100, 100, 50, 20, 400, 300, 1, {});
    EXPECT_GT(right.x0, 100);
    EXPECT_GT(right.y0, 100);
    const LayoutRect atEdge = askedPixelLabelBox(380, 290, 50, 20, 400, 300, 1, {});
    EXPECT_FALSE(atEdge.overlaps({378, 288, 382, 292}));  // beside the pixel, not over it, inside the window
    EXPECT_TRUE((LayoutRect{10, 10, 390, 290}).contains(atEdge));
    const LayoutRect panel{0, 0, 200, 300};
    const LayoutRect clear = askedPixelLabelBox(210, 100, 150, 20, 400, 300, 1, {panel});
    EXPECT_FALSE(clear.overlaps(panel));
    EXPECT_LE(clear.x1, 390);
}

TEST(AskedPixelLabelWindow, AMutantsFunctionAndBothValuesOnThePicture) {
    Xvfb x;
    TempDir dir;
    const LabelCase cases[] = {
        {"05-ggx", "missing-pi", "", 320, 240, 1, "D_GGX"},
        {"11-environment", "no-inv-pi", "scenes/environments/sky-spheres.json", 640, 360, 2, "environmentShading"},
        {"03-lambert", "missing-pi", "", 960, 540, 3, "Fd_Lambert"},
    };
    std::vector<std::unique_ptr<Process>> runs;
    {
        auto context = createHeadlessContext(Backend::Auto);
        for (const LabelCase& c : cases) {
            const fs::path impl = mutantFolder(dir.path(), c.unit, c.mutant);
            const Scene scene = *c.scene ? loadSceneFile((sourceRoot() / c.scene).string()).scene : defaultScene();
            const auto [px, py] = changedPixel(Implementation{impl, {}}, scene, c.width, c.height);
            ASSERT_GE(px, 0) << c.unit << ": the mistake changes no pixel";
            const std::string name = c.unit;
            writeText(dir / (name + ".txt"), "wait 1\nui-scale " + std::to_string(c.scale) + "\nwait 1\npick " +
                                                 std::to_string(px) + " " + std::to_string(py) + "\nwait 1\nlayout " +
                                                 name + ".json\nscreenshot " + name + ".png ui\nquit\n");
            std::vector<std::string> argv = {RAYLAB_BINARY, "view"};
            if (*c.scene) argv.push_back((sourceRoot() / c.scene).string());
            for (const std::string& a : {std::string("--size"), std::to_string(c.width) + "x" + std::to_string(c.height),
                                         std::string("--impl"), impl.string(), std::string("--script"), name + ".txt"})
                argv.push_back(a);
            runs.push_back(std::make_unique<Process>(argv, windowEnv(x), dir.path()));
        }
    }
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const LabelCase& c = cases[k];
        const std::string name = c.unit;
        const RunResult r = runs[k]->wait(std::chrono::seconds(240));
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        // What the label reads: the function and its exercise, both values.
        const std::size_t at = r.out.find("raylab: on the picture: [");
        ASSERT_NE(at, std::string::npos) << name << ": " << r.out;
        const std::string label = r.out.substr(at, r.out.find('\n', at) - at);
        EXPECT_NE(label.find(std::string(c.function) + " in " + c.unit), std::string::npos) << label;
        EXPECT_NE(label.find("[here "), std::string::npos) << label;
        EXPECT_NE(label.find("[model "), std::string::npos) << label;
        // Where the window drew it: inside, clear of the panel and the rest.
        const LayoutReport report = parseLayoutJson(readText(dir / (name + ".json")), name + ".json");
        const LayoutBox* box = find(report, "asked pixel label");
        ASSERT_NE(box, nullptr) << name << ": no label in the layout report";
        EXPECT_FLOAT_EQ(report.uiScale, float(c.scale));
        EXPECT_FALSE(box->rect.empty()) << name;
        for (const std::string& p : layoutProblems(report))
            if (p.find("asked pixel label") != std::string::npos)
                ADD_FAILURE() << name << ": " << p << "\n" << r.err.substr(r.err.size() > 1500 ? r.err.size() - 1500 : 0);
        // The label is on the window's picture: dark box, bright text inside it.
        const DisplayImage image = readPng((dir / (name + ".png")).string());
        int bright = 0;
        for (int y = int(box->rect.y0) + 1; y < int(box->rect.y1) - 1 && y < image.height; ++y)
            for (int xx = int(box->rect.x0) + 1; xx < int(box->rect.x1) - 1 && xx < image.width; ++xx)
                if (image.at(xx, y)[0] > 200) ++bright;
        EXPECT_GT(bright, 20) << name << ": no text in the label's box";
    }
}
