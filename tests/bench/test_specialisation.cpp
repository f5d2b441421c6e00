// Shaders specialised to their scene (app/render/define_table.h) and the
// early stop of the mirror bounces (app/render/bounce_cutoff.h,
// shaders/trace.glsl): the specialised picture matches the CPU reference
// within the core's budget and the generic shader, the defines follow the
// scene's structure only, and each step of the bound behind the early stop
// holds. No timing is asserted anywhere: `raylab bench` measures speed.
#include "core/paths.h"
#include "core/scene_io.h"
#include "reference/cpu_reference.h"
#include "render/bounce_cutoff.h"
#include "render/gl_renderer.h"
#include "core/file_io.h"
#include "core/float_range.h"
#include "render/define_table.h"
#include "shader/shader_library.h"
#include "bench/bench_test_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

using namespace rl;
namespace fs = std::filesystem;

namespace {

ShaderDefines with(ShaderDefines defines, const ShaderDefines& more) {
    for (const auto& [name, value] : more) defines[name] = value;
    return defines;
}

// The three programs a scene can get: `raylab render` (specialised to the
// structure, the picture and where things are), the live window's
// (specialised, every view), `render --generic`.
ShaderDefines pictureDefines(const Scene& s, const Implementation& impl) {
    return definesFor(s, implementationFacts(impl), Purpose::Picture);
}
ShaderDefines renderDefines(const Scene& s, const fs::path& impl = solutionsDir()) {
    return pictureDefines(s, Implementation{impl, {}});
}
ShaderDefines fullDefines(const Scene& s) { return definesFor(s, ImplementationFacts{}, Purpose::EveryView); }
ShaderDefines genericDefines(const Scene& s) { return definesFor(s, ImplementationFacts{}, Purpose::Generic); }
const ShaderDefines kPictureOnly{{"RL_PICTURE_ONLY", "1"}};

Rendering renderWith(const Scene& scene, const ShaderDefines& defines, const fs::path& impl = solutionsDir()) {
    test::ensureHeadlessContext();
    ShaderProgram program = buildRayTracer(Implementation{impl, {}}, defines);
    return renderOnce(program, scene, frameFromScene(scene));
}

Scene sized(Scene s, int w = 128, int h = 96) {
    s.render.width = w;
    s.render.height = h;
    return s;
}

Scene load(const fs::path& path) { return loadSceneFile(path.string()).scene; }

std::vector<fs::path> jsonFilesIn(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(dir))
        // Scenes only: scenes/scene.schema.json is the format's JSON Schema.
        if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
            out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

fs::path deepBounceScene() { return sourceRoot() / "tests" / "bench" / "deep-bounces.json"; }

double maxComponent(glm::dvec3 v) { return std::max(v.x, std::max(v.y, v.z)); }
double minComponent(glm::dvec3 v) { return std::min(v.x, std::min(v.y, v.z)); }

// Deterministic pseudo-random numbers in [0, 1) (xorshift).
struct Random {
    std::uint64_t state;
    explicit Random(std::uint64_t seed) : state(seed * 0x9E3779B97F4A7C15ull + 1) {}
    double next() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return double(state >> 11) * 0x1.0p-53;
    }
    double range(double lo, double hi) { return lo + (hi - lo) * next(); }
    glm::dvec3 direction() {  // uniform on the sphere
        double z = range(-1, 1), phi = range(0, 6.283185307179586);
        double r = std::sqrt(std::max(0.0, 1 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

// Every scene the bound tests run on: the bundled ones and the bench's deep
// one. Not environment scenes: the bound leaves environment light out, and
// the cutoff is off where there is one (define_table.cpp, RL_BOUNCE_CUTOFF).
std::vector<Scene> boundScenes() {
    std::vector<Scene> out;
    for (const fs::path& f : jsonFilesIn(scenesDir())) out.push_back(load(f));
    for (const fs::path& f : jsonFilesIn(scenesDir() / "presets"))
        if (Scene s = load(f); !s.environment) out.push_back(s);
    out.push_back(load(deepBounceScene()));
    return out;
}

}  // namespace

// ---- the specialised picture against the reference and the generic shader --------------

TEST(Specialisation, EveryBundledSceneMatchesTheReferenceAndTheGenericShader) {
    std::vector<fs::path> files = jsonFilesIn(scenesDir());
    for (const fs::path& f : jsonFilesIn(scenesDir() / "presets")) files.push_back(f);
    files.push_back(deepBounceScene());
    ASSERT_GE(files.size(), 6u);
    for (const fs::path& file : files) {
        Scene s = sized(load(file));
        std::string name = file.filename().string();
        // Environment light is approximated in GL (docs/model.md): its error
        // has its own budget, held by EnvironmentBudget (tests/bench/test_environment_sweep.cpp).
        if (s.environment) continue;
        Rendering reference = ref::renderCpu(s);
        Rendering specialised = renderWith(s, renderDefines(s));
        Rendering generic = renderWith(s, genericDefines(s));
        test::expectWithinBudget(specialised, reference, name + ": specialised (render) vs CPU reference");
        test::expectWithinBudget(generic, reference, name + ": generic vs CPU reference");
        test::expectWithinBudget(specialised, generic, name + ": specialised (render) vs generic");
        test::expectWithinBudget(renderWith(s, fullDefines(s)), generic, name + ": specialised (every view) vs generic");
    }
}

// The hard cases have their own budgets against the reference
// (tests/accuracy); specialising must not change their pictures.
TEST(Specialisation, HardScenesRenderAsWithTheGenericShader) {
    std::vector<fs::path> files = jsonFilesIn(scenesDir() / "hard");
    ASSERT_GE(files.size(), 10u);
    for (const fs::path& file : files) {
        Scene s = load(file);
        std::string name = file.filename().string();
        Rendering generic = renderWith(s, genericDefines(s));
        test::expectWithinBudget(renderWith(s, renderDefines(s)), generic, name + ": specialised (render) vs generic");
        test::expectWithinBudget(renderWith(s, fullDefines(s)), generic, name + ": specialised (every view) vs generic");
    }
}

TEST(Specialisation, SpecialisedRenderMatchesAtFourSamplesAndEveryDisplayStep) {
    Scene base = sized(load(scenesDir() / "lecture.json"), 64, 48);
    base.render.spp = 4;
    for (ToneMap op : {ToneMap::Reinhard, ToneMap::Exponential, ToneMap::None})
        for (bool srgb : {false, true}) {
            Scene s = base;
            s.render.tonemap = op;
            s.render.srgb = srgb;
            test::expectWithinBudget(renderWith(s, renderDefines(s)), ref::renderCpu(s),
                               "tone map " + toneMapName(op) + (srgb ? ", sRGB" : ", gamma 2.2"));
        }
}

// A course half done: exercises 01..k solved, the rest the shipped stubs.
// The specialised picture (with its stub frame) is the generic one at every stage.
TEST(Specialisation, EveryStageOfTheCourseRendersAsWithTheGenericShader) {
    fs::path dir = test::freshTempDir("spec_stages");
    Scene s = sized(load(scenesDir() / "lecture.json"), 64, 48);
    for (int k = 0; k <= 10; ++k) {
        fs::path impl = dir / ("stage" + std::to_string(k));
        fs::create_directories(impl);
        for (const auto& entry : fs::directory_iterator(exercisesDir())) {
            if (entry.path().extension() != ".glsl") continue;
            std::string name = entry.path().filename().string();
            int number = std::stoi(name.substr(0, 2));
            fs::copy_file(number <= k ? solutionsDir() / name : entry.path(), impl / name);
        }
        Rendering generic = renderWith(s, genericDefines(s), impl);
        ImageDiff d = compareRenderings(renderWith(s, renderDefines(s, impl), impl), generic);
        SCOPED_TRACE("exercises 01.." + std::to_string(k) + " solved: " + test::describe(d));
        EXPECT_LE(d.offFraction, 0.005);
        EXPECT_LT(d.meanLsb, 0.2);
        EXPECT_EQ(d.nonFinite, 0);
    }
}

// One sphere needs no shadow ray (RL_SINGLE_SPHERE): from outside it shadows
// nothing, from inside it hides the lights outside it. Camera and one light
// inside, one light outside, no bounces.
TEST(Specialisation, SingleSphereShadowsWithoutShadowRaysSeenFromInside) {
    Scene s;
    s.camera.position = {0, 0, 0.5};
    s.camera.target = {0, 0, -1};
    s.render.maxBounces = 0;
    s.spheres.push_back({{0, 0, 0}, 2.0, {}});
    s.lights.push_back({{0.5, 0.8, -0.5}, {1, 1, 1}, 3});
    s.lights.push_back({{0, 0, -5}, {1, 0.5, 0.2}, 40});  // outside: must be hidden everywhere inside
    s = sized(s, 96, 72);
    ShaderDefines defines = renderDefines(s);
    ASSERT_TRUE(defines.count("RL_SINGLE_SPHERE"));
    test::expectWithinBudget(renderWith(s, defines), ref::renderCpu(s), "inside one sphere");
    // And from outside, lit by both lights.
    s.camera.position = {0, 0, 6};
    s.camera.target = {0, 0, 0};
    s.lights[1].position = {3, 3, 4};
    test::expectWithinBudget(renderWith(s, renderDefines(s)), ref::renderCpu(s), "outside one sphere");
}

// ---- which defines ------------------------------------------------------------------------

TEST(Specialisation, DefinesChangeOnlyWithStructure) {
    Scene base = load(scenesDir() / "lecture.json");
    ShaderDefines defines = fullDefines(base);

    // Values: every one of them leaves the program as it is.
    std::vector<std::pair<std::string, Scene>> values;
    auto value = [&](const std::string& what, auto change) {
        Scene s = base;
        change(s);
        values.push_back({what, s});
    };
    value("sphere centre", [](Scene& s) { s.spheres[2].center.x += 0.3; });
    value("sphere radius", [](Scene& s) { s.spheres[2].radius *= 1.5; });
    value("albedo", [](Scene& s) { s.spheres[3].material.albedo = {0.3, 0.2, 0.1}; });
    value("roughness", [](Scene& s) { s.spheres[3].material.roughness = 0.05; });
    value("metallic of a metal", [](Scene& s) { s.spheres[1].material.metallic = 0.5; });
    value("ao", [](Scene& s) { s.spheres[1].material.ao = 0.2; });
    value("light position", [](Scene& s) { s.lights[0].position = {1, 2, 3}; });
    value("light colour and intensity", [](Scene& s) { s.lights[1].color = {1, 0, 0}, s.lights[1].intensity = 400; });
    value("ambient", [](Scene& s) { s.render.ambient = 0.2; });
    value("background", [](Scene& s) { s.render.background = {1, 1, 1}; });
    value("exposure", [](Scene& s) { s.render.exposure = 3; });
    value("tone map", [](Scene& s) { s.render.tonemap = ToneMap::Exponential; });
    value("gamma", [](Scene& s) { s.render.gamma = 1.0; });
    value("sRGB", [](Scene& s) { s.render.srgb = true; });
    value("samples per pixel", [](Scene& s) { s.render.spp = 9; });
    value("size", [](Scene& s) { s.render.width = 33, s.render.height = 17; });
    value("camera", [](Scene& s) { s.camera.position = {4, 4, 4}, s.camera.fovYDegrees = 20; });
    for (const auto& [what, s] : values) EXPECT_EQ(fullDefines(s), defines) << what;

    // Structure: every one of these needs another program.
    std::vector<std::pair<std::string, Scene>> structures;
    auto structure = [&](const std::string& what, auto change) {
        Scene s = base;
        change(s);
        structures.push_back({what, s});
    };
    structure("one sphere more", [](Scene& s) { s.spheres.push_back(s.spheres.back()); });
    structure("one light less", [](Scene& s) { s.lights.pop_back(); });
    structure("bounce limit", [](Scene& s) { s.render.maxBounces = 3; });
    structure("no bounces", [](Scene& s) { s.render.maxBounces = 0; });
    structure("model", [](Scene& s) { s.model.distribution = DistributionModel::Beckmann; });
    structure("one sphere", [](Scene& s) { s.spheres.resize(1); });
    for (const auto& [what, s] : structures) EXPECT_NE(fullDefines(s), defines) << what;

    // The generic shader does not depend on the scene at all (reference model).
    for (const auto& [what, s] : values) EXPECT_EQ(genericDefines(s), genericDefines(base)) << what;
    for (const auto& [what, s] : structures)
        if (s.model.isReference()) EXPECT_EQ(genericDefines(s), genericDefines(base)) << what;
}

TEST(Specialisation, CountsBounceLimitAndFeatures) {
    ShaderDefines lecture = fullDefines(load(scenesDir() / "lecture.json"));
    EXPECT_EQ(lecture["RL_SPHERE_COUNT"], "6");
    EXPECT_EQ(lecture["RL_LIGHT_COUNT"], "2");
    EXPECT_EQ(lecture["RL_MAX_BOUNCES"], "2");
    EXPECT_FALSE(lecture.count("RL_BOUNCE_CUTOFF"));  // two bounces: not worth its test
    EXPECT_FALSE(lecture.count("RL_SINGLE_SPHERE"));
    EXPECT_FALSE(lecture.count("RL_PICTURE_ONLY"));  // only `raylab render` adds it, for the picture

    Scene dielectric = load(scenesDir() / "dielectric-row.json");
    ShaderDefines d = fullDefines(dielectric);
    EXPECT_EQ(d["RL_MAX_BOUNCES"], "0");
    EXPECT_FALSE(d.count("RL_BOUNCE_CUTOFF"));  // nothing to stop

    Scene deep = load(deepBounceScene());
    EXPECT_TRUE(fullDefines(deep).count("RL_BOUNCE_CUTOFF"));  // eight bounces

    Scene variant = load(deepBounceScene());
    variant.model.diffuse = DiffuseModel::Burley;
    EXPECT_FALSE(fullDefines(variant).count("RL_BOUNCE_CUTOFF"));  // the bound is for the reference model
    EXPECT_TRUE(fullDefines(variant).count("RL_FD_BURLEY"));
    EXPECT_TRUE(genericDefines(variant).count("RL_FD_BURLEY"));  // the model is in the generic shader too

    EXPECT_EQ(renderDefines(load(scenesDir() / "lecture.json")).count("RL_PICTURE_ONLY"), 1u);
}

// ---- what a program for one picture compiles in (Purpose::Picture) ------------------------

// The residual form of makeHit is compiled in for the huge spheres near the
// scene's anchor (the frame of every hit point, sceneAnchor()) only: the
// lecture's ground (radius 1000 or 1e5), none of the metal row's spheres, not
// the radius-4 sphere around camera-inside's spheres (its bound can be at
// most 2.9 times the centre form's smaller there). The anchor is the
// scene's, not the camera's: the ground seen from afar keeps it; the small
// spheres lifted far above the ground take the anchor away from it.
TEST(PictureValues, ResidualFormOnlyForHugeSpheresNearTheAnchor) {
    EXPECT_EQ(renderDefines(load(scenesDir() / "lecture.json")).at("RL_RESIDUAL_SPHERES"), "1");
    EXPECT_EQ(renderDefines(load(scenesDir() / "metal-row.json")).at("RL_RESIDUAL_SPHERES"), "0");
    EXPECT_EQ(renderDefines(load(scenesDir() / "hard" / "camera-inside.json")).at("RL_RESIDUAL_SPHERES"), "0");
    Scene lecture = load(scenesDir() / "lecture.json");
    lecture.spheres[0].radius = 1e5;
    lecture.spheres[0].center.y = -1e5;
    EXPECT_EQ(renderDefines(lecture).at("RL_RESIDUAL_SPHERES"), "1");
    lecture = load(scenesDir() / "lecture.json");
    lecture.camera.position = {0, 2000, 3000};
    lecture.camera.target = {0, 0, -3};
    EXPECT_EQ(renderDefines(lecture).at("RL_RESIDUAL_SPHERES"), "1");
    for (std::size_t i = 1; i < lecture.spheres.size(); ++i) lecture.spheres[i].center.y += 2000;
    EXPECT_EQ(renderDefines(lecture).at("RL_RESIDUAL_SPHERES"), "0");
}

// The camera's position in the anchor frame is compiled in as the float32 the
// scene block holds: the lecture's camera (0, 1.1, 2.2) against the anchor,
// the centre of its small spheres' box (0.025, 0.375, -2.8) (the ground left out).
TEST(PictureValues, CameraIsCompiledInRelativeToTheAnchor) {
    Scene lecture = load(scenesDir() / "lecture.json");
    glm::dvec3 anchor = sceneAnchor(lecture);
    EXPECT_NEAR(anchor.x, 0.025, 1e-15);
    EXPECT_NEAR(anchor.y, 0.375, 1e-15);
    EXPECT_NEAR(anchor.z, -2.8, 1e-15);
    glm::vec3 e(lecture.camera.position - anchor);
    char expected[128];
    std::snprintf(expected, sizeof expected, "vec3(%.9g, %.9g, %.1f)", double(e.x), double(e.y), double(e.z));
    ASSERT_EQ(e.z, 5.0f);  // an integer value: written 5.0, a GLSL float
    EXPECT_EQ(renderDefines(lecture).at("RL_CAMERA_FROM_ANCHOR"), expected);
}

// The stub tests are compiled out only when no exercise file can return
// NOT_STARTED: the solutions yes; the shipped stubs, a file that names it in
// code, no; a file that names it in a comment only, yes.
TEST(PictureValues, StubTestsDroppedOnlyWhenEveryExerciseIsWritten) {
    EXPECT_TRUE(implementationFacts(Implementation{solutionsDir(), {}}).exercisesFinished);
    EXPECT_FALSE(implementationFacts(Implementation{exercisesDir(), {}}).exercisesFinished);
    fs::path dir = test::freshTempDir("finished_exercises");
    std::string file = readRegularFile(solutionsDir() / "07-fresnel.glsl", 1 << 20);
    writeFileAtomic(dir / "code.glsl", file + "\nfloat unfinishedHelper() { return NOT_STARTED; }\n");
    writeFileAtomic(dir / "comment.glsl", file + "\n// returned NOT_STARTED until it was written\n/* NOT_STARTED */\n");
    EXPECT_FALSE(implementationFacts(Implementation{solutionsDir(), {{"07-fresnel.glsl", dir / "code.glsl"}}}).exercisesFinished);
    EXPECT_TRUE(implementationFacts(Implementation{solutionsDir(), {{"07-fresnel.glsl", dir / "comment.glsl"}}}).exercisesFinished);
    // And `raylab render`'s program has it with the solutions, not with a stub left.
    Scene lecture = load(scenesDir() / "lecture.json");
    EXPECT_EQ(renderDefines(lecture).count("RL_EXERCISES_FINISHED"), 1u);
    EXPECT_EQ(pictureDefines(lecture, Implementation{solutionsDir(), {{"05-ggx.glsl", exercisesDir() / "05-ggx.glsl"}}})
                  .count("RL_EXERCISES_FINISHED"),
              0u);
}

// One program for every set of exercise files (docs/decisions.md, "One
// program"): the course's own, a student's written differently, a file with
// a comment added, a mistake: the same defines, so the same program text
// around the files, and nothing in the table asks whose a file is.
TEST(PictureValues, EveryFilesGetTheSameSpecialisation) {
    Scene lecture = load(scenesDir() / "lecture.json");
    const ShaderDefines course = renderDefines(lecture);
    for (const char* own : {"01-camera--aspect-on-y.glsl", "02-intersect--sign-of-b.glsl",
                            "04-shadows--shadow-ray-shortened.glsl", "09-reflections--full-strength-bounces.glsl"}) {
        const std::string file = std::string(own).substr(0, std::string(own).find("--")) + ".glsl";
        EXPECT_EQ(pictureDefines(lecture, Implementation{solutionsDir(), {{file, test::unitFilePath("mutants", own)}}}),
                  course)
            << own;
    }
    for (const std::string& name : test::unitFileNames("alternatives")) {
        const std::string file = name.substr(0, name.find("--")) + ".glsl";
        EXPECT_EQ(pictureDefines(lecture, Implementation{solutionsDir(), {{file, test::unitFilePath("alternatives", name)}}}),
                  course)
            << name;
    }
    EXPECT_TRUE(course.count(kSkyTilesDefine));
    EXPECT_TRUE(course.count("RL_SHADOW_STEPS(X, Y)"));
    const std::optional<ShaderDefines> sky = skyProgramDefines(course);
    ASSERT_TRUE(sky.has_value());
    EXPECT_EQ(sky->at("RL_SKY"), "1");
    EXPECT_EQ(sky->at("RL_SPHERE_COUNT"), course.at("RL_SPHERE_COUNT"));  // every ray still tested
    EXPECT_TRUE(marksPixels(course));
    EXPECT_FALSE(marksPixels(withoutAssumptions(course)));
}

// The picture through `raylab render`'s path (renderOnce: the picture
// program, its sky tiles' program, and the marked pixels drawn again by the
// program without assumptions) is the generic program's, pixel for pixel,
// for files whose shadow ray or camera ray the assumptions do not cover: a
// shadow ray cut short or sent past the light, a camera ray squeezed or
// turned, an intersection that takes the far root. Without the exact pass
// the same files draw another picture: the assumptions were tested.
TEST(PictureValues, MistakesTheAssumptionsDoNotCoverDrawAsTheyCompute) {
    test::ensureHeadlessContext();
    const Scene lecture = sized(load(scenesDir() / "lecture.json"), 96, 72);
    const Scene between = load(scenesDir() / "hard" / "light-between.json");  // a sphere beyond the light
    auto generic = [](const Implementation& impl, const Scene& s) {
        ShaderProgram program = buildRayTracer(impl, genericDefines(s));
        return renderOnce(program, s, frameFromScene(s));
    };
    for (const char* own : {"04-shadows--shadow-ray-shortened.glsl", "04-shadows--occluders-beyond-light.glsl",
                            "01-camera--aspect-on-y.glsl", "02-intersect--far-root-first.glsl",
                            "04-shadows--offset-into-surface.glsl"}) {
        const std::string file = std::string(own).substr(0, std::string(own).find("--")) + ".glsl";
        const Implementation impl{solutionsDir(), {{file, test::unitFilePath("mutants", own)}}};
        for (const Scene* s : {&lecture, &between}) {
            SCOPED_TRACE(std::string(own) + (s == &lecture ? " on the lecture" : " on light-between"));
            PictureProgram picture = buildPictureProgram(impl, pictureDefines(*s, impl));
            const Rendering expected = generic(impl, *s);
            ImageDiff d = compareRenderings(renderOnce(picture, *s, frameFromScene(*s)), expected);
            SCOPED_TRACE(test::describe(d));
            EXPECT_LE(d.maxLsb, 1);
            EXPECT_EQ(d.nonFinite, 0);
            if (file == "04-shadows.glsl" && std::string(own).find("offset") == std::string::npos)
                EXPECT_TRUE(picture.exact) << "a shadow ray that does not end at the light marks its pixels";
        }
    }
    // Without its exact pass, the ray sent past the light is answered up
    // to the light: the sphere beyond it casts no shadow there.
    const Implementation beyond{solutionsDir(), {{"04-shadows.glsl", test::unitFilePath("mutants", "04-shadows--occluders-beyond-light.glsl")}}};
    PictureProgram unchecked = buildPictureProgram(beyond, pictureDefines(between, beyond));
    GlRenderer renderer;
    renderer.setScene(between);
    renderer.draw(unchecked, frameFromScene(between));
    EXPECT_TRUE(renderer.lastFrameMarked());
    EXPECT_GT(compareRenderings(renderer.readBack(), generic(beyond, between)).offFraction, 0.01);
}

// The shadow test from the light's side (shaders/shadow_light_side.glsl)
// only where it is exact: not for a sphere that meets, touches or repeats
// another (a shadow ray starts on one surface near the other's), not for the
// huge spheres whose roots the shader refines, not for a light far beyond
// the scene's spheres or on a surface; and its pictures are the segment
// test's within the core's budget on the bundled hard scenes.
TEST(PictureValues, LightSideOnlyWhereExact) {
    auto steps = [](const Scene& s) {
        const ShaderDefines d = renderDefines(s);
        return d.count("RL_SHADOW_STEPS(X, Y)") ? d.at("RL_SHADOW_STEPS(X, Y)") : std::string("none");
    };
    EXPECT_EQ(steps(load(scenesDir() / "hard" / "overlapping.json")), "none");
    Scene lecture = load(scenesDir() / "lecture.json");
    EXPECT_EQ(steps(lecture), " Y(0) X(1) X(2) X(3) X(4) X(5)");  // the ground: refined
    Scene touching = lecture;
    touching.spheres[2].center = touching.spheres[1].center + glm::dvec3(1.0, 0.0, 0.0);  // radius 0.5 each
    EXPECT_EQ(steps(touching), " Y(0) Y(1) Y(2) X(3) X(4) X(5)");
    Scene far = lecture;
    far.lights[1].position = {300, 2, -1};
    EXPECT_EQ(steps(far), "none");
    // 30 spheres and 6 lights: 180 pairs; 64 spheres and 16 lights: more
    // than the compile budget.
    Scene random30 = load(sourceRoot() / "tests" / "bench" / "random-30.json");
    EXPECT_NE(steps(random30), "none");
    Scene crowd = random30;
    while (crowd.spheres.size() < std::size_t(kMaxSpheres)) crowd.spheres.push_back(crowd.spheres.back());
    crowd.lights.resize(std::size_t(kMaxLights), crowd.lights[0]);
    EXPECT_EQ(steps(crowd), "none");
    for (const fs::path& f : jsonFilesIn(scenesDir() / "hard")) {
        SCOPED_TRACE(f.filename().string());
        const Scene s = load(f);
        const ShaderDefines picture = renderDefines(s);
        if (!picture.count("RL_SHADOW_STEPS(X, Y)")) continue;
        test::expectWithinBudget(renderWith(s, withoutAssumptions(picture)), renderWith(s, picture),
                                 "light side against segment test");
    }
}

// The bench's own scenes through `raylab render`'s program: within the core's
// budget of the CPU reference, and of the program without the picture's
// layers (the scene's numbers compiled in, residual set, sample grid, stub
// tests, the light's side).
TEST(PictureValues, BenchScenesRenderAsWithoutThePictureValues) {
    for (const char* name : {"course-row-ground.json", "random-30.json"}) {
        Scene s = sized(load(sourceRoot() / "tests" / "bench" / name));
        Rendering picture = renderWith(s, renderDefines(s));
        test::expectWithinBudget(picture, ref::renderCpu(s), std::string(name) + ": render vs CPU reference");
        test::expectWithinBudget(picture, renderWith(s, with(fullDefines(s), kPictureOnly)),
                           std::string(name) + ": render vs structure and picture only");
    }
}

// ---- the bound behind the early stop, one step at a time ----------------------------------

// Step 1: no hit sends more than hitRadianceBound, whatever the view.
TEST(BounceCutoff, NoHitIsBrighterThanTheHitBound) {
    Random random(7);
    for (const Scene& scene : boundScenes()) {
        double H = hitRadianceBound(scene);
        ASSERT_TRUE(std::isfinite(H)) << scene.sourcePath;
        ref::CameraBasis camera = ref::cameraBasis(scene.camera);
        double brightest = 0;
        for (int k = 0; k < 4000; ++k) {
            glm::dvec3 dir = glm::normalize(camera.forward + 0.8 * random.direction());
            ref::Hit hit;
            if (!ref::closestHit(scene, camera.position, dir, hit)) continue;
            for (glm::dvec3 v : {-dir, random.direction()}) {
                if (glm::dot(v, hit.n) <= 0) v = -v;
                brightest = std::max(brightest, maxComponent(ref::shadeHit(scene, hit, v)));
            }
        }
        EXPECT_LE(brightest, H) << scene.sourcePath;
        EXPECT_GT(brightest, 0.0) << scene.sourcePath;
    }
}

// The bound is not loose by orders: a metal sphere reflecting a light
// straight back (n.h = 1, D at its peak) sends k times the bound, k the
// Schlick-GGX constant, because the bound also takes G1(NoV)/NoV at its own
// peak 1/k (grazing view), which D's peak never meets.
TEST(BounceCutoff, HitBoundIsReachedByASpecularPeak) {
    Scene s;
    s.render.ambient = 0;
    Material m;
    m.albedo = {1, 1, 1};
    m.roughness = 0.3;
    m.metallic = 1;
    s.spheres.push_back({{0, 0, 0}, 1.0, m});
    s.lights.push_back({{0, 0, 3}, {1, 1, 1}, 10});
    ref::Hit hit;
    ASSERT_TRUE(ref::closestHit(s, {0, 0, 5}, {0, 0, -1}, hit));
    double peak = maxComponent(ref::shadeHit(s, hit, {0, 0, 1}));
    double H = hitRadianceBound(s);
    double k = (0.3 + 1) * (0.3 + 1) / 8;
    EXPECT_LE(peak, H);
    EXPECT_GT(peak, 0.95 * k * H);
}

// Step 2: no ray brings back more than rayRadianceBound for the hits it may make.
TEST(BounceCutoff, NoRayIsBrighterThanTheRayBound) {
    Random random(11);
    for (Scene scene : boundScenes()) {
        ref::CameraBasis camera = ref::cameraBasis(scene.camera);
        for (int bounces : {0, 1, 3}) {
            scene.render.maxBounces = bounces;
            double R = rayRadianceBound(scene, bounces + 1);
            double brightest = 0;
            for (int k = 0; k < 2000; ++k) {
                glm::dvec3 dir = glm::normalize(camera.forward + 0.8 * random.direction());
                brightest = std::max(brightest, maxComponent(ref::traceRadiance(scene, camera.position, dir)));
            }
            EXPECT_LE(brightest, R) << scene.sourcePath << ", " << bounces << " bounces";
        }
    }
}

// Step 3: the display step is concave, so its slope at a bounds every rise above a.
TEST(BounceCutoff, DisplaySlopeBoundsEveryRiseOfTheDisplayStep) {
    Random random(3);
    for (ToneMap op : {ToneMap::Reinhard, ToneMap::Exponential, ToneMap::None})
        for (int g = 0; g < 3; ++g) {
            RenderSettings r;
            r.tonemap = op;
            r.exposure = 1;  // c is exposed radiance already
            r.srgb = g == 2;
            r.gamma = g == 0 ? 2.2 : 1.0;
            auto display = [&](double c) { return ref::displayEncode(glm::dvec3(c), r).x; };
            for (int k = 0; k < 20000; ++k) {
                double a = std::pow(10.0, random.range(-6, 2));
                double d = std::pow(10.0, random.range(-8, 1));
                double rise = display(a + d) - display(a);
                EXPECT_LE(rise, displaySlope(r, a) * d * (1 + 1e-9) + 1e-15)
                    << toneMapName(op) << " gamma case " << g << ", a " << a << ", d " << d;
            }
            // The C++ twin of the shader's slope is the derivative (finite differences, away from kinks).
            for (double a : {0.01, 0.2, 0.7, 3.0}) {
                double h = 1e-6 * a;
                double numeric = (display(a + h) - display(a - h)) / (2 * h);
                EXPECT_NEAR(displaySlope(r, a), numeric, 1e-4 * std::max(1.0, numeric))
                    << toneMapName(op) << " gamma case " << g << " at " << a;
            }
        }
}

// Steps 1-3 together, in double precision: a CPU trace that stops where the
// shader's test (mirrored here) says so stays within the tolerance of the
// full trace in every pixel, and does stop in most of the deep-bounce scene.
namespace {

bool cannotChangeOutput(const glm::vec4& u, const RenderSettings& r, glm::dvec3 radiance, glm::dvec3 throughput) {
    double a = double(u.y) * minComponent(radiance);
    return displaySlope(r, a) * maxComponent(throughput) <= kBounceCutoffTolerance * double(u.x);
}

glm::dvec3 traceWithCutoff(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, bool& stopped) {
    glm::vec4 u = bounceCutoffUniform(scene);
    glm::dvec3 radiance(0.0), throughput(1.0);
    stopped = false;
    for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce) {
        if (bounce > 0 && cannotChangeOutput(u, scene.render, radiance, throughput)) {
            stopped = true;
            break;
        }
        ref::Hit hit;
        if (!ref::closestHit(scene, origin, dir, hit)) {
            radiance += throughput * scene.render.background;
            break;
        }
        radiance += throughput * ref::shadeHit(scene, hit, -dir);
        const Material& m = scene.spheres[size_t(hit.sphere)].material;
        double NoV = std::clamp(glm::dot(hit.n, -dir), 1e-4, 1.0);
        throughput *= ref::F_SchlickRoughness(ref::baseReflectance(m), NoV, m.roughness);
        origin = ref::offsetRayOrigin(hit.p, hit.n, hit.magnitude);
        dir = glm::reflect(dir, hit.n);  // as ref::traceRadiance does
    }
    return radiance;
}

}  // namespace

TEST(BounceCutoff, StoppedTraceStaysWithinTheToleranceOfTheFullTrace) {
    for (int spp : {1, 4}) {
        Scene scene = sized(load(deepBounceScene()), 64, 48);
        scene.render.spp = spp;
        ref::CameraBasis camera = ref::cameraBasis(scene.camera);
        int n = int(std::lround(std::sqrt(double(spp))));
        long stoppedSamples = 0, samples = 0;
        double worst = 0;
        for (int j = 0; j < scene.render.height; ++j)
            for (int i = 0; i < scene.render.width; ++i) {
                glm::dvec3 cut(0.0);
                for (int s = 0; s < spp; ++s) {
                    glm::dvec2 offset = ref::sampleOffset(s, n);
                    glm::dvec3 dir = ref::cameraRayDirection(
                        glm::dvec2(i, j) + offset, glm::dvec2(scene.render.width, scene.render.height),
                        camera.fovYRadians, camera.right, camera.up, camera.forward);
                    bool stopped = false;
                    cut += traceWithCutoff(scene, camera.position, dir, stopped);
                    stoppedSamples += stopped;
                    ++samples;
                }
                cut /= double(spp);
                glm::dvec3 full = ref::pixelRadiance(scene, camera, i, j);
                glm::dvec3 change = ref::displayEncode(full, scene.render) - ref::displayEncode(cut, scene.render);
                worst = std::max(worst, std::max(std::abs(change.x), std::max(std::abs(change.y), std::abs(change.z))));
            }
        EXPECT_LE(worst, kBounceCutoffTolerance) << spp << " spp";
        EXPECT_GT(double(stoppedSamples) / double(samples), 0.5) << spp << " spp: the stop should fire in this scene";
    }
}

// Where the bound does not exist, the shader must never stop early.
TEST(BounceCutoff, UnboundedScenesNeverStop) {
    Scene lecture = load(scenesDir() / "lecture.json");
    EXPECT_GT(bounceCutoffUniform(lecture).x, 0.0f);

    Scene touching = lecture;  // a light on a sphere's surface: no finite bound
    touching.lights[0].position = touching.spheres[2].center + glm::dvec3(0, touching.spheres[2].radius, 0);
    EXPECT_FALSE(std::isfinite(hitRadianceBound(touching)));
    EXPECT_EQ(bounceCutoffUniform(touching).x, 0.0f);

    Scene convex = lecture;  // gamma < 1: the display step is not concave
    convex.render.gamma = 0.5;
    EXPECT_EQ(bounceCutoffUniform(convex).x, 0.0f);

    Scene variant = lecture;  // the bound is derived for the reference model only
    variant.model.blinnPhong = true;
    EXPECT_FALSE(std::isfinite(hitRadianceBound(variant)));
    EXPECT_EQ(bounceCutoffUniform(variant).x, 0.0f);

    // With x = 0 only a zero throughput (nothing more can be added) stops.
    glm::vec4 u = bounceCutoffUniform(touching);
    EXPECT_FALSE(cannotChangeOutput(u, touching.render, glm::dvec3(5.0), glm::dvec3(1e-30)));
    EXPECT_TRUE(cannotChangeOutput(u, touching.render, glm::dvec3(5.0), glm::dvec3(0.0)));
}

// The GPU side: in the deep-bounce scene the specialised shader stops early
// in most pixels and still matches the reference, and the generic shader
// (which traces every bounce) to within the tolerance, i.e. one 8-bit step.
TEST(BounceCutoff, SpecialisedShaderStopsWithinOneStepOfTheFullTrace) {
    for (int spp : {1, 4}) {
        Scene s = sized(load(deepBounceScene()), 96, 72);
        s.render.spp = spp;
        Rendering specialised = renderWith(s, renderDefines(s));
        test::expectWithinBudget(specialised, ref::renderCpu(s), std::to_string(spp) + " spp: specialised vs reference");
        ImageDiff d = compareRenderings(specialised, renderWith(s, genericDefines(s)));
        SCOPED_TRACE(std::to_string(spp) + " spp, specialised vs generic: " + test::describe(d));
        EXPECT_LE(d.offFraction, 0.001);  // float noise between two programs aside, at most one step
        EXPECT_LE(d.maxLsb, 2);
        EXPECT_LT(d.meanLsb, 0.05);
    }
}
