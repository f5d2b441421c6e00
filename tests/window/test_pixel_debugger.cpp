// The pixel debugger (render/pixel_debugger.h; docs/lecture.md, "Ask a
// pixel"): the GL program of the implementation on screen, asked at one
// pixel, against the CPU reference. Most cases use the headless entry point
// `raylab render --ask X,Y --impl DIR` as a user types it; one case clicks
// in a real window (Xvfb) with two implementations side by side.
#include "window/view_harness.h"

#include "checks/probe_cases.h"
#include "checks/probe_runner.h"
#include "core/float_range.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "render/pixel_debugger.h"
#include "shader/shader_library.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace rl;
using namespace rl::wintest;
using rl::test::writeText;
namespace fs = std::filesystem;

namespace {

// A copy of solutions/ with one exercise replaced by one of its mutants.
fs::path mutantFolder(const fs::path& root, const std::string& unit, const std::string& mutant) {
    return rl::test::solutionsWithMutant(root, unit + ".glsl", sourceRoot() / "course" / unit / "mutants" / (mutant + ".glsl"));
}

using rl::test::kBeyondScene;  // 04's mutant shows at its wall's centre

struct MutantCase {
    const char* unit;
    const char* mutant;
    const char* pixel;  // X,Y from the top left, on the default scene at 64x48 (or kBeyondScene)
    bool beyondScene = false;
};

// One mutant of each exercise, at a pixel its mistake changes (found with
// `raylab render --ask`): the camera ray (01), the hit (02), Lambert (03),
// the visibility (04), D (05), G (06), F (07), the
// specular term (08), the bounce's weight (09), the display colour (10).
const MutantCase kMutants[] = {
    {"01-camera", "upside-down", "32,22"},
    {"02-intersect", "sign-of-b", "32,22"},
    {"03-lambert", "missing-pi", "32,22"},
    {"04-shadows", "occluders-beyond-light", "16,12", true},
    {"05-ggx", "missing-pi", "32,22"},
    {"06-geometry", "ibl-k", "32,22"},
    {"07-fresnel", "power-on-voh", "32,22"},
    {"08-cook-torrance", "missing-four", "32,22"},
    {"09-reflections", "full-strength-bounces", "32,22"},
    {"10-display", "gamma-before-tonemap", "32,22"},
};

std::string lineStarting(const std::string& out, const std::string& start) {
    const std::string text = "\n" + out;  // the answer is the first line
    const std::size_t at = text.find("\n" + start);
    if (at == std::string::npos) return "";
    return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

}  // namespace

// For a mutant of each exercise the first value that differs is in that
// exercise's function, and the checker's probes of that exercise, run on
// the same code, fail with a hint. All ten run at once (2 cores: ~20 s).
TEST(PixelDebugger, FindsEachMutantInItsOwnExercise) {
    TempDir dir;
    writeText(dir / "beyond.json", kBeyondScene);
    std::vector<std::unique_ptr<Process>> runs;
    for (const MutantCase& m : kMutants) {
        const fs::path impl = mutantFolder(dir.path(), m.unit, m.mutant);
        std::vector<std::string> argv = {RAYLAB_BINARY, "render"};
        if (m.beyondScene) argv.push_back((dir / "beyond.json").string());
        for (const char* a : {"--ask", m.pixel, "--impl"}) argv.push_back(a);
        argv.push_back(impl.string());
        if (!m.beyondScene) argv.insert(argv.end(), {"--size", "64x48"});
        fs::create_directories(dir / (std::string(m.unit) + ".out"));
        runs.push_back(std::make_unique<Process>(argv, std::map<std::string, std::string>{},
                                                 dir / (std::string(m.unit) + ".out")));
    }
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const MutantCase& m = kMutants[k];
        const RunResult r = runs[k]->wait(std::chrono::seconds(180));
        ASSERT_EQ(r.status, 0) << m.unit << ": " << r.err;
        const std::string verdict = lineStarting(r.out, "first difference: ");
        EXPECT_NE(verdict.find(std::string(" in ") + m.unit + " (course/" + m.unit + "/handout.md)"), std::string::npos)
            << m.unit << "/" << m.mutant << " at " << m.pixel << ": " << r.out;
        // The table marks that value first (">> NN").
        EXPECT_NE(r.out.find(std::string(">> ") + std::string(m.unit).substr(0, 2) + " "), std::string::npos)
            << m.unit << ": " << r.out;
        const std::string hint = lineStarting(r.out, std::string("checker, ") + m.unit + "'s probes on this code: ");
        EXPECT_NE(hint, "") << m.unit << ": " << r.out;
        EXPECT_EQ(hint.find("every case passes"), std::string::npos) << m.unit << ": " << hint;
    }
}

// The solutions: no value differs beyond the tolerance at any pixel of a
// small picture of the default scene (the lecture scene: spheres, ground,
// sky, the bounces between them), nor of the metal and dielectric rows with
// reflections (roughness 0 to 1, mirror bounces between spheres), nor of an
// environment scene with a sun and of one with spheres resting on a ground
// (exercise 11's terms beside the approximation's, 12's form factors).
TEST(PixelDebugger, SolutionsAgreeWithTheReferenceEverywhere) {
    auto context = createHeadlessContext(Backend::Auto);
    const Implementation impl{sourceRoot() / "solutions", {}};
    for (const std::string& file : {std::string(""), (sourceRoot() / "scenes" / "metal-row-reflections.json").string(),
                                    (sourceRoot() / "scenes" / "dielectric-row-reflections.json").string(),
                                    (sourceRoot() / "scenes" / "environments" / "sky-spheres.json").string(),
                                    (sourceRoot() / "scenes" / "environments" / "contact.json").string()}) {
        const Scene scene = file.empty() ? defaultScene() : loadSceneFile(file).scene;
        const ShaderProgram program = buildPixelDebugProgram(impl, scene);
        const int w = 32, h = 18;
        int asked = 0;
        double worst = 0;
        std::string worstAt;
        for (int j = 0; j < h; j += 1)
            for (int i = 0; i < w; i += 1) {
                const PixelDebug d = debugPixel(program, scene, scene.camera, w, h, i, j, "solutions");
                ++asked;
                EXPECT_EQ(d.firstDifference, -1) << (file.empty() ? "default scene" : file) << " pixel (" << i << ", "
                                                 << j << "): " << pixelDebugVerdict(d);
                EXPECT_FALSE(d.values.empty());
                for (const PixelValue& v : d.values)
                    if (v.toleranceUsed > worst) {
                        worst = v.toleranceUsed;
                        worstAt = v.name() + " at (" + std::to_string(i) + ", " + std::to_string(j) + ")";
                    }
            }
        EXPECT_EQ(asked, w * h);
        // The margin the tolerance leaves (docs/lecture.md quotes it).
        std::cout << (file.empty() ? "default scene" : file) << ": the largest |GL - reference| is " << worst
                  << " of its tolerance (" << worstAt << ")\n";
    }
}

// The program's values are its exercise functions' own: the recorded E and
// Lambert (03), D (05), G (06), F (07), diffuse and specular (08) and the
// display colour (10) equal a probe of the same functions
// (checks/probe_runner.h) on the inputs the program recorded beside them,
// for the solutions and the mutants of 05, 06, 07, 08 and 10.
TEST(PixelDebugger, RecordedValuesEqualAProbeOfTheSameInputs) {
    auto context = createHeadlessContext(Backend::Auto);
    TempDir dir;
    const Scene scene = defaultScene();
    struct Folder { std::string unit; fs::path dir; };
    const std::vector<Folder> folders = {{"", sourceRoot() / "solutions"},
                                         {"05-ggx", mutantFolder(dir.path(), "05-ggx", "missing-pi")},
                                         {"06-geometry", mutantFolder(dir.path(), "06-geometry", "ibl-k")},
                                         {"07-fresnel", mutantFolder(dir.path(), "07-fresnel", "one-plus-f0")},
                                         {"08-cook-torrance", mutantFolder(dir.path(), "08-cook-torrance", "missing-four")},
                                         {"10-display", mutantFolder(dir.path(), "10-display", "gamma-before-tonemap")}};
    for (const Folder& folder : folders) {
        const Implementation impl{folder.dir, {}};
        const PixelDebug d = debugPixel(buildPixelDebugProgram(impl, scene), scene, scene.camera, 64, 48, 12, 23,
                                        folder.dir.filename().string());
        auto value = [&](PixelValueKind kind, int bounce, int light) -> const PixelValue* {
            for (const PixelValue& v : d.values)
                if (v.kind == kind && v.bounce == bounce && v.light == light) return &v;
            return nullptr;
        };
        int compared = 0;
        for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce)
            for (int light = 0; light < int(scene.lights.size()); ++light) {
                const PixelValue* n = value(PixelValueKind::Normal, bounce, -1);
                const PixelValue* hv = value(PixelValueKind::Half, bounce, light);
                const PixelValue* angles = value(PixelValueKind::Angles, bounce, light);
                const PixelValue* alpha = value(PixelValueKind::Alpha, bounce, light);
                const PixelValue* f0 = value(PixelValueKind::F0, bounce, light);
                const PixelValue* hit = value(PixelValueKind::Hit, bounce, -1);
                if (!n || !hv || !angles || !alpha || !f0 || !hit) continue;
                const Material& m = scene.spheres[std::size_t(hit->gl.y)].material;
                // name, exercise, inputs (a, b, c texels), the recorded value
                struct Probe { const char* name; int exercise; std::array<float, 12> in; PixelValueKind kind; int outs; };
                const std::vector<Probe> probes = {
                    {"D_GGX", 5, {float(n->gl.x), float(n->gl.y), float(n->gl.z), 0, float(hv->gl.x), float(hv->gl.y),
                                  float(hv->gl.z), 0, float(alpha->gl.x), 0, 0, 0}, PixelValueKind::D, 1},
                    {"G_SchlickGGX", 6, {float(angles->gl.y), float(angles->gl.x), float(m.roughness), 0}, PixelValueKind::G, 1},
                    {"F_Schlick", 7, {float(f0->gl.x), float(f0->gl.y), float(f0->gl.z), float(angles->gl.z)},
                     PixelValueKind::F, 3},
                    {"Fd_Lambert", 3, {float(m.albedo.x), float(m.albedo.y), float(m.albedo.z), 0}, PixelValueKind::Lambert, 3},
                };
                // 03's irradiance, 08's BRDF and 10's display step on the recorded
                // inputs: p relative to the anchor as the shader holds it, v = -ray.
                const PixelValue* p = value(PixelValueKind::Point, bounce, -1);
                const PixelValue* ray = value(PixelValueKind::Ray, bounce, -1);
                const PixelValue* l = value(PixelValueKind::LightDir, bounce, light);
                const PixelValue* E = value(PixelValueKind::Irradiance, bounce, light);
                const PixelValue* visibility = value(PixelValueKind::Visibility, bounce, light);
                ASSERT_TRUE(p && ray && l && E && visibility);
                const glm::dvec3 anchor = sceneAnchor(scene);
                const glm::vec3 pShader = shaderPosition(p->gl, anchor, 1.0),
                                lightShader = shaderPosition(scene.lights[std::size_t(light)].position, anchor, 1.0);
                const glm::dvec3 I = scene.lights[std::size_t(light)].color * scene.lights[std::size_t(light)].intensity;
                const glm::vec3 nf(n->gl), vf(-glm::vec3(ray->gl)), lf(l->gl);
                const std::array<float, 24> brdfIn = {float(m.albedo.x), float(m.albedo.y), float(m.albedo.z), float(m.roughness),
                                                      float(m.metallic), float(m.ao), 0, 0, nf.x, nf.y, nf.z, 0, vf.x, vf.y, vf.z, 0,
                                                      lf.x, lf.y, lf.z, 0};
                struct Wide { const char* name; int exercise; std::array<float, 24> in; PixelValueKind kind; bool timesE; };
                const std::vector<Wide> wide = {
                    {"pointLightIrradiance", 3, {pShader.x, pShader.y, pShader.z, 0, nf.x, nf.y, nf.z, 0, lightShader.x,
                                                 lightShader.y, lightShader.z, 0, float(I.x), float(I.y), float(I.z), 0},
                     PixelValueKind::Irradiance, false},
                    {"diffuseBRDF", 8, brdfIn, PixelValueKind::Diffuse, true},
                    {"specularBRDF", 8, brdfIn, PixelValueKind::Specular, true},
                };
                for (const Wide& w : wide) {
                    const PixelValue* recorded = value(w.kind, bounce, light);
                    ASSERT_NE(recorded, nullptr) << w.name;
                    if (w.timesE && visibility->gl.x <= 0) continue;  // recorded as 0: nothing to compare
                    const ShaderProgram probe(assembleShader("fullscreen.vert", impl, {}),
                                              assembleShader("probe.frag", impl,
                                                             {{"RL_PROBE_EXERCISE", std::to_string(w.exercise)}}));
                    ProbeSpec spec(w.name, w.name, 3);
                    ProbeCase c;
                    c.in = w.in;
                    spec.cases.push_back(c);
                    const std::vector<std::array<float, 4>> out = runProbe(probe, spec, nullptr);
                    for (int k = 0; k < 3; ++k) {
                        // As above; times E: one more float32 product.
                        const double got = w.timesE ? double(out[0][std::size_t(k)] * float(E->gl[k])) : out[0][std::size_t(k)];
                        EXPECT_NEAR(got, recorded->gl[k], 1e-6 * std::abs(recorded->gl[k]) + 1e-12)
                            << folder.dir.filename() << " " << w.name << " " << recorded->name();
                    }
                    ++compared;
                }
                for (const Probe& p : probes) {
                    const PixelValue* recorded = value(p.kind, bounce, light);
                    ASSERT_NE(recorded, nullptr) << p.name;
                    const ShaderProgram probe(assembleShader("fullscreen.vert", impl, {}),
                                              assembleShader("probe.frag", impl,
                                                             {{"RL_PROBE_EXERCISE", std::to_string(p.exercise)}}));
                    ProbeSpec spec(p.name, p.name, p.outs);
                    ProbeCase c;
                    std::copy(p.in.begin(), p.in.end(), c.in.begin());
                    spec.cases.push_back(c);
                    const std::vector<std::array<float, 4>> out = runProbe(probe, spec, nullptr);
                    for (int k = 0; k < p.outs; ++k)
                        // The same function on the same float inputs, compiled into
                        // another program: the compiler may contract a*b+c into an FMA
                        // differently, a few float32 roundings (1e-6 relative).
                        EXPECT_NEAR(out[0][std::size_t(k)], recorded->gl[k], 1e-6 * std::abs(recorded->gl[k]) + 1e-12)
                            << folder.dir.filename() << " " << p.name << " " << recorded->name();
                    ++compared;
                }
            }
        // 10's display step on the recorded radiance (the scene's exposure, tone map, gamma).
        {
            const PixelValue* radiance = value(PixelValueKind::Radiance, 0, -1);
            const PixelValue* display = value(PixelValueKind::Display, 0, -1);
            ASSERT_TRUE(radiance && display);
            const RenderSettings& r = scene.render;
            const ShaderProgram probe(assembleShader("fullscreen.vert", impl, {}),
                                      assembleShader("probe.frag", impl, {{"RL_PROBE_EXERCISE", "10"}}));
            ProbeSpec spec("displayEncode", "displayEncode", 3);
            ProbeCase c;
            c.in = {float(radiance->gl.x), float(radiance->gl.y), float(radiance->gl.z), float(r.exposure),
                    float(int(r.tonemap)), r.srgb ? 0.0f : float(r.gamma)};
            spec.cases.push_back(c);
            const std::vector<std::array<float, 4>> out = runProbe(probe, spec, nullptr);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(std::clamp(double(out[0][std::size_t(k)]), 0.0, 1.0), display->gl[k],
                            1e-6 * std::abs(display->gl[k]) + 1e-12)
                    << folder.dir.filename() << " displayEncode";
            ++compared;
        }
        EXPECT_GE(compared, 8) << folder.dir.filename() << ": the pixel must hit a lit sphere";
        if (!folder.unit.empty()) {
            ASSERT_NE(d.first(), nullptr) << folder.unit;
            EXPECT_EQ(d.first()->exercise, std::stoi(folder.unit.substr(0, 2))) << pixelDebugVerdict(d);
        }
    }
}

// A real window, two implementations side by side: a pick in the left half
// (a 05 mutant) names D in 05-ggx, a pick at the same pixel of the right
// half (the solutions) finds every value within tolerance.
TEST(PixelDebuggerWindow, BothHalvesOfASideBySideAnswerForTheirOwnCode) {
    Xvfb x;
    TempDir dir;
    const fs::path mutant = mutantFolder(dir.path(), "05-ggx", "missing-pi");
    // 2 x 64 columns, 48 rows: each half a 64x48 picture, letterboxed.
    writeText(dir / "script.txt", "wait 1\npick 32 24\nwait 1\npick 96 24\nwait 1\nquit\n");
    const RunResult r = runRaylab({"view", "--size", "128x48", "--no-panel", "--no-captions", "--side-by-side", "--impl",
                                   mutant.string(), "--compare", (sourceRoot() / "solutions").string(), "--script",
                                   "script.txt"},
                                  windowEnv(x), dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::size_t left = r.out.find("of the left picture"), right = r.out.find("of the right picture");
    ASSERT_NE(left, std::string::npos) << r.out;
    ASSERT_NE(right, std::string::npos) << r.out;
    ASSERT_LT(left, right);
    const std::string leftAnswer = r.out.substr(left, right - left), rightAnswer = r.out.substr(right);
    EXPECT_NE(leftAnswer.find("first difference: primary hit, lights[0]: D = D_GGX"), std::string::npos) << leftAnswer;
    EXPECT_NE(leftAnswer.find("in 05-ggx"), std::string::npos) << leftAnswer;
    EXPECT_NE(leftAnswer.find("checker, 05-ggx's probes on this code: D_GGX"), std::string::npos) << leftAnswer;
    EXPECT_NE(rightAnswer.find("every value within float32 tolerance"), std::string::npos) << rightAnswer;
}

// The student fixes the file while the window is open: the next pick asks
// the new code (the debugger's program is built again after the reload).
TEST(PixelDebuggerWindow, APickAfterAReloadAsksTheNewCode) {
    Xvfb x;
    TempDir dir;
    const fs::path impl = mutantFolder(dir.path(), "05-ggx", "missing-pi");
    writeText(dir / "script.txt",
              "wait 1\npick 32 22\nwait 1\nscreenshot asked.png\nwait-reload 60\nwait 1\npick 32 22\nwait 1\nquit\n");
    Process view({RAYLAB_BINARY, "view", "--size", "64x48", "--no-panel", "--no-captions", "--impl", impl.string(),
                  "--script", "script.txt"},
                 windowEnv(x), dir.path());
    ASSERT_TRUE(waitForFile(dir / "asked.png", std::chrono::seconds(90)));
    writeText(impl / "05-ggx.glsl.new", rl::test::readText(sourceRoot() / "solutions" / "05-ggx.glsl"));
    fs::rename(impl / "05-ggx.glsl.new", impl / "05-ggx.glsl");  // one step, as editors save
    const RunResult r = view.wait(std::chrono::seconds(120));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::size_t reloaded = r.out.find("raylab: reloaded");
    ASSERT_NE(reloaded, std::string::npos) << r.out;
    EXPECT_NE(r.out.substr(0, reloaded).find("first difference: primary hit, lights[0]: D = D_GGX"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("every value within float32 tolerance", reloaded), std::string::npos) << r.out.substr(reloaded);
    EXPECT_EQ(r.out.find("first difference", reloaded), std::string::npos) << r.out.substr(reloaded);
}

// A pixel outside the picture (however large its number), a malformed
// --ask, and --ask with --cpu, --hdr, -o or a --view: one line naming the
// option, exit 1, no table.
TEST(PixelDebugger, RefusesAPixelItCannotAsk) {
    TempDir dir;
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"render", "--ask", "64,10", "--size", "64x48"},
          std::vector<std::string>{"render", "--ask", "ten,ten"}, std::vector<std::string>{"render", "--ask", "1,1", "--cpu"},
          // Numbers read whole: no wrap-around to (0, 0), no sign or tail dropped.
          std::vector<std::string>{"render", "--ask", "4294967296,0"},
          std::vector<std::string>{"render", "--ask", "0,18446744073709551616000"},
          std::vector<std::string>{"render", "--ask", "1,1x"}, std::vector<std::string>{"render", "--ask", "+1,1"},
          // Options of a picture are refused, not dropped.
          std::vector<std::string>{"render", "--ask", "1,1", "--hdr", "x.pfm"},
          std::vector<std::string>{"render", "--ask", "1,1", "--view", "d"},
          std::vector<std::string>{"render", "--ask", "1,1", "-o", "x.png"}}) {
        const RunResult r = runRaylab(args, {}, dir.path());
        EXPECT_EQ(r.status, 1) << args[2];
        EXPECT_EQ(r.err.rfind("raylab: error: --ask: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.out.find("first difference"), std::string::npos) << r.out;
    }
}
