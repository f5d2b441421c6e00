// Temporary: definesFor() (render/define_table.h) against the functions it
// replaces (old_defines.cpp, their last version), for every scene under
// scenes/ (presets and hard included) and tests/bench/, eight
// implementations and every purpose. Removed with old_defines.cpp once
// tests/unit/defines.golden records the same.
#include "bench/bench.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/define_table.h"
#include "unit/old_defines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>

using namespace rl;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> allScenes() {
    std::vector<fs::path> out;
    for (const fs::path& dir : {scenesDir(), scenesDir() / "presets", scenesDir() / "hard", sourceRoot() / "tests" / "bench"})
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
                out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

struct Impl {
    const char* name;
    Implementation impl;
    int checked;  // the exercise a checker run replaces (0: none)
};

std::vector<Impl> impls() {
    const fs::path m = sourceRoot() / "tests" / "mutants";
    return {
        {"solutions", {solutionsDir(), {}}, 0},
        {"stubs", {exercisesDir(), {}}, 0},
        {"stubs+course-09", {exercisesDir(), {{"09-reflections.glsl", solutionsDir() / "09-reflections.glsl"}}}, 0},
        {"student-01", {solutionsDir(), {{"01-camera.glsl", m / "01-camera--aspect-on-y.glsl"}}}, 1},
        {"student-02", {solutionsDir(), {{"02-intersect.glsl", m / "02-intersect--far-root-first.glsl"}}}, 2},
        {"student-04", {solutionsDir(), {{"04-shadows.glsl", m / "04-shadows--offset-into-surface.glsl"}}}, 4},
        {"stub-05", {solutionsDir(), {{"05-ggx.glsl", exercisesDir() / "05-ggx.glsl"}}}, 5},
        {"student-09", {solutionsDir(), {{"09-reflections.glsl", m / "09-reflections--full-strength-bounces.glsl"}}}, 9},
        {"student-07", {solutionsDir(), {{"07-fresnel.glsl", m / "07-fresnel--one-plus-f0.glsl"}}}, 7},
    };
}

std::vector<ShadingModel> models() {
    std::vector<ShadingModel> out;
    ShadingModel m;
    m.distribution = DistributionModel::Beckmann;
    out.push_back(m);
    m.geometry = GeometryModel::SmithGGXSeparable;
    out.push_back(m);
    m.geometry = GeometryModel::SmithGGXCorrelated;
    m.fresnel = FresnelModel::Dielectric;
    out.push_back(m);
    m.fresnel = FresnelModel::Conductor;
    m.diffuse = DiffuseModel::Burley;
    out.push_back(m);
    m.blinnPhong = true;
    out.push_back(m);
    return out;
}

}  // namespace

TEST(DefineTableVsOld, EveryScenePurposeAndImplementation) {
    int compared = 0;
    const std::vector<Impl> cases = impls();
    for (const fs::path& file : allScenes()) {
        Scene base = loadSceneFile(file.string()).scene;
        std::vector<ShadingModel> variants = models();
        variants.insert(variants.begin(), base.model);  // first the scene's own
        for (std::size_t k = 0; k < variants.size(); ++k) {
            Scene scene = base;
            scene.model = variants[k];
            const std::string at = file.filename().string();
            EXPECT_EQ(definesFor(scene, {}, Purpose::Generic), old::shaderDefinesFor(scene, false)) << at;
            EXPECT_EQ(modelDefines(scene.model), old::modelDefines(scene.model)) << at;
            EXPECT_EQ(definesFor(scene, {}, Purpose::EveryView), old::shaderDefinesFor(scene, true)) << at;
            ShaderDefines genericPicture = old::shaderDefinesFor(scene, false);
            genericPicture.merge(old::pictureOnlyDefines());
            EXPECT_EQ(definesFor(scene, {}, Purpose::GenericPicture), genericPicture) << at;
            compared += 4;
            for (const Impl& c : cases) {
                const ImplementationFacts facts = implementationFacts(c.impl);
                const ShaderDefines oldPicture = old::renderProgramDefines(scene, c.impl);
                const ShaderDefines picture = definesFor(scene, facts, Purpose::Picture);
                EXPECT_EQ(picture, oldPicture) << at << " " << c.name;
                EXPECT_EQ(skyProgramDefines(picture), old::skyProgramDefines(oldPicture)) << at << " " << c.name;
                const bool started = old::traceStarted(c.impl);
                const ShaderDefines files = old::fileDefines(c.impl);
                EXPECT_EQ(definesFor(scene, facts, Purpose::LiveView),
                          old::liveViewDefines(scene, scene.model, View::Final, started, files))
                    << at << " " << c.name;
                EXPECT_EQ(definesFor(scene, facts, Purpose::Generic),
                          old::liveViewDefines(scene, scene.model, View::D, started, files))
                    << at << " " << c.name;
                compared += 4;
            }
            if (k != 0) continue;
            // The bench's layers sweep: the same rows (its order is now the table's).
            bench::Options layers;
            layers.sweeps = {"layers"};
            std::set<std::string> got, want;
            for (const bench::Variant& v : bench::makeVariants(scene, layers)) got.insert(v.name);
            ShaderDefines all = old::specialisationDefines(scene);
            for (const auto& [name, value] : old::renderProgramDefines(scene, Implementation{solutionsDir(), {}}))
                all[name] = value;
            for (const char* name : {"RL_EXERCISES_FINISHED", "RL_CANDIDATE_SHADOWS", "RL_SHADOW_CONES", "RL_CAMERA_OUTSIDE",
                                     "RL_SEGMENT_TEST", "RL_RESIDUAL_SPHERES", "RL_SAMPLE_GRID", "RL_SELECT_LIGHTS",
                                     old::kSkyTilesDefine})
                if (all.count(name)) want.insert(std::string("without:") + name);
            if (scene.spheres.size() <= 31 && !scene.lights.empty() && !all.count("RL_CANDIDATE_SHADOWS"))
                want.insert("with:RL_CANDIDATE_SHADOWS");
            EXPECT_EQ(got, want) << at;
        }
    }
    // The checker's program: the old rule was "not for 09"; the new one
    // trusts the course's 09 only, which is the same for every check but
    // that of 09 with the solution's own text (docs/decisions.md).
    for (const Impl& c : cases) {
        if (c.checked == 0) continue;
        const ShaderDefines old = c.checked == 9 ? ShaderDefines{} : old::pictureOnlyDefines();
        EXPECT_EQ(definesFor(Scene{}, implementationFacts(c.impl), Purpose::Probe), old) << c.name;
    }
    std::cout << compared << " define sets compared\n";
}
