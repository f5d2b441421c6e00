// The pixel debugger names the exercise of every mistake the course ships
// (render/pixel_debugger.h; issues 34 and 37): for each unit with a function
// the debugger records (askedFunctions(), the names its units declare in
// course/*/unit.json), each of its mutants in place of its solution, a
// picture of a scene the unit shows in (its "shows_with" define: an
// environment scene for RL_ENVIRONMENT) is compared with the solutions', and
// at the pixels the mistake changes most and at the middle of the changed
// ones, the debugger's first difference is in that unit, the answer does not
// say the pixel agrees, and its label (the view's) names the unit.
#include "core/paths.h"
#include "core/scene_io.h"
#include "course/exercise_registry.h"
#include "gl/context.h"
#include "render/define_table.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "render/pixel_debugger.h"
#include "shader/shader_library.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace rl;
namespace fs = std::filesystem;

namespace {

// A copy of solutions/ with one exercise's file replaced by `mutant`.
fs::path mutantFolder(const fs::path& root, const ExerciseInfo& unit, const fs::path& mutant) {
    return rl::test::solutionsWithMutant(root, unit.file(), mutant);
}

using rl::test::kBeyondScene;

// The scenes a unit is tried on, in order, until its mutant changes a pixel.
std::vector<Scene> scenesFor(const ExerciseInfo& unit, const fs::path& tmp) {
    std::vector<Scene> out;
    auto sized = [](Scene s) {
        s.render.width = 48;
        s.render.height = 36;
        s.render.spp = 1;
        return s;
    };
    if (unit.showsWith == "RL_ENV_OCCLUSION") {  // 12-sky-shadows: spheres near each other under a sky
        for (const char* file : {"scenes/environments/contact.json", "scenes/presets/11-environment-contact.json",
                                 "scenes/environments/sky-spheres.json"})
            out.push_back(sized(loadSceneFile((sourceRoot() / file).string()).scene));
        return out;
    }
    if (unit.showsWith == "RL_ENVIRONMENT") {
        for (const char* file : {"scenes/environments/sky-spheres.json", "scenes/environments/studio-spheres.json",
                                 "scenes/presets/11-environment-contact.json"})
            out.push_back(sized(loadSceneFile((sourceRoot() / file).string()).scene));
        // Mirrors: roughness 0, where the prefiltered chain's level 0 is used,
        // under the sky and under the studio: its soft boxes' sharp edges tell
        // level 0 from level 1 (roughness 1/15), which a sky without its sun
        // does not by an 8-bit step.
        for (std::size_t k : {std::size_t(0), std::size_t(1)}) {
            Scene mirrors = out[k];
            for (Sphere& s : mirrors.spheres) s.material.roughness = 0.0;
            out.push_back(mirrors);
        }
        return out;
    }
    out.push_back(sized(defaultScene()));
    rl::test::writeText(tmp / "beyond.json", kBeyondScene);
    out.push_back(loadSceneFile((tmp / "beyond.json").string()).scene);
    out.push_back(sized(loadSceneFile((sourceRoot() / "scenes/metal-row-reflections.json").string()).scene));
    return out;
}

DisplayImage picture(const Implementation& impl, const Scene& scene) {
    FrameSettings frame = frameFromScene(scene);
    return renderOnce(buildPictureProgram(impl, definesFor(scene, implementationFacts(impl), Purpose::Picture)), scene,
                      frame)
        .display;
}

}  // namespace

TEST(AskEveryMutant, NamesTheMutatedUnitAtAChangedPixel) {
    auto context = createHeadlessContext(Backend::Auto);
    const fs::path tmp = rl::test::freshTempDir("ask-every-mutant");
    const Implementation solutions{sourceRoot() / "solutions", {}};
    const std::vector<std::string> asked = askedFunctions();
    int units = 0, pixels = 0;
    std::size_t mutants = 0;
    std::vector<std::string> unchanged;
    for (const ExerciseInfo& unit : allExercises()) {
        const bool askable = std::any_of(unit.functions.begin(), unit.functions.end(), [&](const ExerciseFunction& f) {
            return std::find(asked.begin(), asked.end(), f.name) != asked.end();
        });
        const fs::path dir = sourceRoot() / unit.unitDir() / "mutants";
        if (!askable || !fs::is_directory(dir)) continue;
        ++units;
        const std::vector<Scene> scenes = scenesFor(unit, tmp);
        std::vector<DisplayImage> references;
        for (const Scene& s : scenes) references.push_back(picture(solutions, s));
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".glsl") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& file : files) {
            ++mutants;
            const Implementation impl{mutantFolder(tmp, unit, file), {}};
            const std::string name = unit.id + "/" + file.stem().string();
            bool found = false;
            for (std::size_t k = 0; k < scenes.size() && !found; ++k) {
                const Scene& scene = scenes[k];
                const DisplayImage got = picture(impl, scene);
                // The changed pixels (by 2 or more in 8 bits, any channel: a
                // change of 1 can be a rounding the mistake tips over while
                // the value moves by far less than the display's tolerance),
                // the largest change first.
                std::vector<std::pair<int, int>> changed;  // (-change, index)
                for (int p = 0; p < got.width * got.height; ++p) {
                    int change = 0;
                    for (int c = 0; c < 3; ++c)
                        change = std::max(change, std::abs(int(got.rgb[std::size_t(3 * p + c)]) -
                                                           int(references[k].rgb[std::size_t(3 * p + c)])));
                    if (change >= 2) changed.push_back({-change, p});
                }
                if (changed.empty()) continue;
                found = true;
                const std::vector<int> at = {changed.front().second, changed[changed.size() / 2].second};
                const ShaderProgram program = buildPixelDebugProgram(impl, scene);
                for (int p : at) {
                    const int x = p % got.width, yTop = p / got.width;
                    const PixelDebug d =
                        debugPixel(program, scene, scene.camera, got.width, got.height, x, got.height - 1 - yTop, name);
                    ++pixels;
                    const std::string where = name + " at (" + std::to_string(x) + ", " + std::to_string(yTop) +
                                              ") from the top left: " + pixelDebugVerdict(d);
                    ASSERT_NE(d.first(), nullptr) << where;
                    EXPECT_EQ(d.first()->exercise, unit.number) << where;
                    EXPECT_FALSE(d.pixelAgrees) << where;
                    EXPECT_EQ(pixelDebugVerdict(d).rfind("first difference: ", 0), 0u) << where;
                    const std::vector<std::string> label = pixelDebugLabel(d);
                    ASSERT_EQ(label.size(), 3u) << where;
                    EXPECT_NE(label[0].find(" in " + unit.id), std::string::npos) << where << " | " << label[0];
                }
            }
            if (!found) unchanged.push_back(name);
            // A unit that shows only with a define (11's environment) is tried
            // on scenes made for it: each of its mistakes shows there.
            EXPECT_TRUE(found || unit.showsWith.empty()) << name << " changes no pixel of its unit's scenes";
        }
    }
    std::cout << units << " units, " << mutants << " mutants, " << pixels << " pixels asked; no pixel changed by "
              << unchanged.size() << ":";
    for (const std::string& u : unchanged) std::cout << " " << u;
    std::cout << "\n";
    EXPECT_GE(units, 11);
    // The others that change no pixel of these small pictures (a different
    // epsilon, a cancelling root) are named above; most must show.
    EXPECT_LE(unchanged.size(), mutants / 2) << "fewer mistakes show than expected";
}
