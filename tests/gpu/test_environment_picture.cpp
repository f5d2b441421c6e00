// The GL picture of environment scenes (issue 24, shaders/environment.glsl):
// scenes without an environment render the same bytes as before it existed;
// with one, the picture follows the exact reference within the
// approximation's bias, and intensity and rotation are values, not programs.
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "reference/environment_reference.h"
#include "render/define_table.h"
#include "render/environment_resources.h"
#include "render/gl_renderer.h"
#include "shader/portability.h"
#include "shader/shader_library.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fs = std::filesystem;
using namespace rl;

namespace {

Scene loaded(const std::string& file, int w, int h) {
    Scene s = loadSceneFile((sourceRoot() / file).string()).scene;
    s.render.width = w;
    s.render.height = h;
    return s;
}

// The relative L1 difference of the radiance: sum |a - b| / sum b over
// every channel (robust where a pixel is nearly black).
double meanRelative(const RadianceImage& got, const RadianceImage& expected) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < got.rgb.size(); ++i) {
        difference += std::abs(double(got.rgb[i]) - double(expected.rgb[i]));
        total += std::abs(double(expected.rgb[i]));
    }
    return difference / total;
}

}  // namespace

// PNGs that the binary built before environment.glsl existed rendered
// (the commit b4ea6dd: `raylab render SCENE --size 64x48 [--generic] -o
// tests/gpu/golden/NAME.png`): the default program and the generic one, on a
// scene of two bounces and one of eight (the bounce cutoff). The default
// program became one for every set of files (docs/decisions.md, "One
// program"): lecture-64x48.png kept its bytes, deep-64x48.png was written
// again by it (one 8-bit step on some pixels, from the bounce cutoff's
// quarter step, against the generated program it replaced).
TEST(EnvironmentPicture, ScenesWithoutOneAreTheSameBytesAsBefore) {
    const fs::path out = test::freshTempDir("env-golden");
    struct Case {
        const char* name;
        const char* scene;
        const char* flags;
    };
    for (const Case& c : {Case{"lecture-64x48", "scenes/lecture.json", ""},
                          Case{"lecture-64x48-generic", "scenes/lecture.json", "--generic"},
                          Case{"deep-64x48", "tests/bench/deep-bounces.json", ""},
                          Case{"deep-64x48-generic", "tests/bench/deep-bounces.json", "--generic"}}) {
        const fs::path png = out / (std::string(c.name) + ".png");
        test::CommandResult r = test::runRaylab("render " + test::shellQuoted((sourceRoot() / c.scene).string()) +
                                                " --size 64x48 " + c.flags + " -o " + test::shellQuoted(png.string()));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(test::readText(png), test::readText(sourceRoot() / "tests/gpu/golden" / (std::string(c.name) + ".png")))
            << c.name << ": not the bytes of the picture before environment light";
    }
}

TEST(EnvironmentPicture, OnlyAnEnvironmentSceneCompilesItIn) {
    Scene plain = loaded("scenes/lecture.json", 32, 24);
    Scene sky = loaded("scenes/environments/sky-spheres.json", 32, 24);
    for (Purpose p : {Purpose::Picture, Purpose::EveryView, Purpose::LiveView, Purpose::Generic}) {
        EXPECT_EQ(definesFor(plain, ImplementationFacts{}, p).count("RL_ENVIRONMENT"), 0u) << purposeName(p);
        EXPECT_EQ(definesFor(sky, ImplementationFacts{}, p).count("RL_ENVIRONMENT"), 1u) << purposeName(p);
    }
}

// WebGL2 compiles the same GLSL: the environment program builds as GLSL ES 3.00.
TEST(EnvironmentPicture, BuildsAsGlslEs) {
    test::renderGl(loaded("scenes/environments/sky-spheres.json", 8, 6));  // the process's context, current
    Implementation solutions{solutionsDir(), {}};
    AssembledSource vertex = assembleShader("fullscreen.vert", solutions, {}, GlslDialect::Es300);
    for (const char* occlusion : {"", "1", "2"}) {  // and with the spheres' shadows (environment_occlusion.glsl)
        ShaderDefines env{{"RL_ENVIRONMENT", "1"}};
        if (*occlusion) env["RL_ENV_OCCLUSION"] = occlusion;
        AssembledSource fragment = assembleShader("main.frag", solutions, env, GlslDialect::Es300);
        EXPECT_EQ(portabilityErrors(fragment), "") << occlusion;
        EXPECT_NO_THROW(ShaderProgram(vertex, fragment)) << occlusion;
    }
}

// A uniform white environment on two spheres 0.1 apart, the reference with
// visibility (each sphere's cap taken out of the other's light in closed
// form, environment_occlusion.glsl, exact for a uniform map but for the
// specular cone's shape): SH9 of a constant is exact and
// the prefiltered map is the constant, so only the split-sum table's
// quadrature and interpolation and the diffuse weight (1 - F0) for
// (1 - F(v.h)) separate the picture from the exact integral, and the
// reference's own noise. Measured: relative L1 difference 0.35%, 8-bit mean
// 0.75 LSB (80x60, 256 reference samples; 0.26% and 0.35 LSB unshadowed against V = 1). The bound 1% leaves room for the
// reference's noise; without the diffuse 1/pi it is 18% off (seen failing),
// and with the level taken as the roughness itself (a mutant of exercise
// 11) the metal sphere is visibly sharper but, in a uniform map, no
// brighter: that mistake is the probes' to find, not this test's.
TEST(EnvironmentPicture, UniformEnvironmentMatchesTheReference) {
    Scene s = parseScene(R"({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y": 45},
        "render": {"width": 80, "height": 60, "max_bounces": 0, "ambient": 0, "tonemap": "none", "gamma": "srgb"},
        "environment": {"file": "white.pfm"}, "lights": [],
        "spheres": [{"center": [-0.55, 0, 0], "radius": 0.5, "material": {"albedo": [0.8, 0.8, 0.8], "roughness": 0.7, "metallic": 0}},
                    {"center": [0.55, 0, 0], "radius": 0.5, "material": {"albedo": [0.9, 0.6, 0.3], "roughness": 0.35, "metallic": 1}}]})",
                         (sourceRoot() / "scenes/environments/uniform.json").string()).scene;
    Rendering gl = test::renderGl(s);
    Rendering cpu = ref::renderCpu(s, 0, ref::EnvironmentOptions{});
    ImageDiff d = compareRenderings(gl, cpu);
    double rel = meanRelative(gl.radiance, cpu.radiance);
    std::printf("uniform environment, GL vs reference: mean relative %.4f, %s\n", rel, test::describe(d).c_str());
    EXPECT_LT(rel, 0.01) << test::describe(d);
    EXPECT_EQ(d.nonFinite, 0);
}

// The shipped scenes: the picture is shadowed by the spheres (issue 34,
// environment_occlusion.glsl), so it is near the exact reference WITH
// visibility and far from the one without (measured at 80x45, 256 samples:
// relative L1 0.029 and 0.17 on the sky, 0.072 and 0.22 on the studio; the
// unshadowed picture was 0.18 and 0.27 from the truth). Bounded against a
// shadow gone missing or wrong.
TEST(EnvironmentPicture, ShippedScenesAgainstTheReference) {
    for (const char* file : {"scenes/environments/sky-spheres.json", "scenes/environments/studio-spheres.json"}) {
        Scene s = loaded(file, 80, 45);
        Rendering gl = test::renderGl(s);
        ref::EnvironmentOptions visible, open;
        open.visibility = false;
        Rendering withV = ref::renderCpu(s, 0, visible);
        Rendering withoutV = ref::renderCpu(s, 0, open);
        ImageDiff a = compareRenderings(gl, withV), b = compareRenderings(gl, withoutV);
        double relA = meanRelative(gl.radiance, withV.radiance), relB = meanRelative(gl.radiance, withoutV.radiance);
        std::printf("%s 80x45, GL vs reference with V: mean relative %.4f, %s\n", file, relA, test::describe(a).c_str());
        std::printf("%s 80x45, GL vs reference without V: mean relative %.4f, %s\n", file, relB, test::describe(b).c_str());
        EXPECT_LT(relA, 0.12) << file;
        EXPECT_LT(relA, 0.5 * relB) << file;
        EXPECT_EQ(a.nonFinite, 0);
    }
}

namespace {
// The sum of the radiance over the pixels x0 <= x < x1, y0 <= y < y1 (row 0 the top).
double boxSum(const RadianceImage& image, int x0, int x1, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) sum += image.at(x, y)[c];
    return sum;
}

// The mean 8-bit difference of a's display from b's over the pixels
// x0 <= x < x1, y0 <= y < y1 (row 0 the top) and the three channels:
// signed (a - b) or its absolute value.
enum class Difference { Signed, Absolute };
double meanDisplayDifference(const Rendering& a, const Rendering& b, int x0, int x1, int y0, int y1,
                             Difference kind) {
    double sum = 0.0;
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c, ++count) {
                const double d = double(a.display.at(x, y)[c]) - b.display.at(x, y)[c];
                sum += kind == Difference::Absolute ? std::abs(d) : d;
            }
    return sum / count;
}
}  // namespace

// Where caps overlap (a ground point under the middle sphere of
// sky-spheres sees the side spheres' caps partly inside the middle one's),
// the light of a shared direction is taken out once: the larger cap keeps
// it (capShareNotCovered, environment_occlusion.glsl). Measured on the
// ground just under the middle sphere (96x72, x 42-54, rows 51-53), GL over
// the reference (256 samples, a sum over 39 pixels: its noise about 2%):
// 0.94 (0.90 with the lens's exact solid angle instead of the smoothstep
// overlap); with each cap taking its whole light (the shared part twice) 0.49,
// the strip half as bright (seen failing). The bound 0.8-1.25 holds
// the shared part once, with room for the reference's noise and the caps'
// approximate mean radiance.
TEST(EnvironmentPicture, OverlappingCapsTakeTheirSharedLightOnce) {
    Scene s = loaded("scenes/environments/sky-spheres.json", 96, 72);
    Rendering gl = test::renderGl(s);
    Rendering cpu = ref::renderCpu(s, 0, ref::EnvironmentOptions{});
    double ratio = boxSum(gl.radiance, 42, 55, 51, 54) / boxSum(cpu.radiance, 42, 55, 51, 54);
    std::printf("sky-spheres, the ground under the middle sphere: GL / reference %.3f\n", ratio);
    EXPECT_GT(ratio, 0.8);
    EXPECT_LT(ratio, 1.25);
}

// Thirteen spheres: twelve balls (radius 0.25-0.35) in two rings on a
// ground, under the sky. A ground point between the balls sees several
// caps overlap, and the shared parts are taken from the two largest caps
// only (capsSeenFrom, environment_occlusion.glsl; docs/decisions.md,
// "Overlaps with the two largest caps only"). Measured at 48x36 against a
// reference of 256 samples (its noise included), mean |GL - reference| over
// the display channels: 1.72 LSB with the two largest, 1.70 with every
// pair, 3.23 with no shared part taken (each cap's whole light: seen
// failing). The bound 2.4 keeps the shared light taken once among many
// spheres, with room for the reference's noise.
TEST(EnvironmentPicture, ManySpheresTakeTheirSharedLightOnce) {
    Scene s = loaded("scenes/environments/sky-spheres.json", 48, 36);
    Sphere ground = s.spheres.back();
    s.spheres.clear();
    for (int i = 0; i < 12; ++i) {
        const double a = i * 2.0 * 3.14159265358979 / 12.0, ring = i % 2 ? 1.2 : 0.7;
        Sphere ball;
        ball.center = {ring * std::cos(a), -0.2 + 0.1 * (i % 3), ring * std::sin(a)};
        ball.radius = 0.25 + 0.05 * (i % 3);
        ball.material.albedo = {0.9, 0.5 + 0.04 * i, 0.3};
        ball.material.roughness = 0.1 + 0.07 * i;
        ball.material.metallic = i % 2;
        s.spheres.push_back(ball);
    }
    s.spheres.push_back(ground);
    Rendering gl = test::renderGl(s);
    Rendering cpu = ref::renderCpu(s, 0, ref::EnvironmentOptions{});
    const double mean = meanDisplayDifference(gl, cpu, 0, 48, 0, 36, Difference::Absolute);
    std::printf("thirteen spheres: mean |GL - reference| %.3f LSB\n", mean);
    EXPECT_LT(mean, 2.4);
}

// The map's sun is a light of its own in the picture (sunLight,
// environment.glsl): the sky without it in SH9's and the prefiltered
// chain's tables, the sun through the scene's BRDF at its disc's nearest
// point. On the copper sphere of sun-spheres (roughness 0.4, its sun
// highlight inside the box x 55-72, rows 29-46 at 96x72), the mean 8-bit
// difference of GL from the reference (256 samples) is measured +1.4 LSB
// (the highlight's peak a little wide); with the sun left out of the
// picture (sunLight returning 0, seen failing) -84. The bound, 3 LSB
// either way, holds the highlight's energy without holding its exact shape.
TEST(EnvironmentPicture, TheSunIsALightOfItsOwn) {
    Scene s = loaded("scenes/environments/sun-spheres.json", 96, 72);
    Rendering gl = test::renderGl(s);
    Rendering cpu = ref::renderCpu(s, 0, ref::EnvironmentOptions{});
    const double mean = meanDisplayDifference(gl, cpu, 55, 73, 29, 47, Difference::Signed);
    std::printf("sun-spheres, the copper sphere: GL - reference %+.2f LSB mean\n", mean);
    EXPECT_LT(std::abs(mean), 3.0);
}

// A rough surface's sun glare is the BRDF's mean over the sun's disc, read
// at the disc's centre with the lobe widened by it (sunLight,
// environment.glsl), not at the disc's point nearest the mirror direction,
// which is its largest. A ground of roughness 0.6 under the sky (whose sun
// is a disc of about 3 degrees), 48x36, the glare in the left third of the
// ground (columns 0-15, rows 16-35, where the view reflects towards the
// sun), mean 8-bit GL - reference (256 samples): measured -0.11 LSB; read
// at the representative point +1.33 (seen failing). The bound 0.7 LSB
// either way holds the glare's energy.
TEST(EnvironmentPicture, ARoughSurfacesSunGlareIsTheDiscsMean) {
    Scene s = loaded("scenes/environments/sky-spheres.json", 48, 36);
    Sphere ground = s.spheres.back();
    ground.material.roughness = 0.6;
    s.spheres = {ground};
    Rendering gl = test::renderGl(s);
    Rendering cpu = ref::renderCpu(s, 0, ref::EnvironmentOptions{});
    const double mean = meanDisplayDifference(gl, cpu, 0, 16, 16, 36, Difference::Signed);
    std::printf("a rough ground's sun glare: GL - reference %+.2f LSB mean\n", mean);
    EXPECT_LT(std::abs(mean), 0.7);
}

// Intensity and rotation are uniforms: the same program draws every value,
// twice the intensity is twice the radiance, and a turn of the map moves the picture.
TEST(EnvironmentPicture, IntensityAndRotationAreValues) {
    Scene s = loaded("scenes/environments/sky-spheres.json", 48, 27);
    Scene brighter = s, turned = s;
    brighter.environment->intensity = 2.0;
    turned.environment->rotationDegrees = 90.0;
    const ImplementationFacts facts{};
    EXPECT_EQ(definesFor(s, facts, Purpose::LiveView), definesFor(brighter, facts, Purpose::LiveView));
    EXPECT_EQ(definesFor(s, facts, Purpose::LiveView), definesFor(turned, facts, Purpose::LiveView));
    Rendering base = test::renderGl(s), twice = test::renderGl(brighter), other = test::renderGl(turned);
    double worst = 0.0;
    for (std::size_t i = 0; i < base.radiance.rgb.size(); ++i)
        worst = std::max(worst, std::abs(twice.radiance.rgb[i] - 2.0 * base.radiance.rgb[i]) /
                                    (2.0 * std::abs(base.radiance.rgb[i]) + 1e-6));
    EXPECT_LT(worst, 1e-5);  // a float32 product per term: a few roundings
    EXPECT_GT(meanRelative(other.radiance, base.radiance), 0.01);
}

// Exercise 11 is optional: a student who has not started it (solutions/
// with 11's shipped stub) gets the same bytes as before on a scene without
// an environment (no stripes, the same program), and the stripes on an
// environment scene, where the exercise shows.
TEST(EnvironmentPicture, AnUnstartedOptionalExerciseShowsOnlyWhereItShows) {
    const fs::path dir = test::freshTempDir("env-stub11");
    for (const auto& f : fs::directory_iterator(solutionsDir())) fs::copy_file(f.path(), dir / f.path().filename());
    fs::copy_file(sourceRoot() / "course/11-environment/stub.glsl", dir / "11-environment.glsl",
                  fs::copy_options::overwrite_existing);
    auto render = [&](const std::string& scene, const std::string& impl, const fs::path& png) {
        test::CommandResult r = test::runRaylab("render " + test::shellQuoted((sourceRoot() / scene).string()) +
                                                " --size 64x48 --impl " + test::shellQuoted(impl) + " -o " +
                                                test::shellQuoted(png.string()));
        ASSERT_EQ(r.status, 0) << r.output;
    };
    render("scenes/lecture.json", dir.string(), dir / "lecture.png");
    EXPECT_EQ(test::readText(dir / "lecture.png"), test::readText(sourceRoot() / "tests/gpu/golden/lecture-64x48.png"));
    render("scenes/environments/sky-spheres.json", dir.string(), dir / "stub.png");
    render("scenes/environments/sky-spheres.json", solutionsDir().string(), dir / "done.png");
    // The top rows are sky in both (the background does not need 11): they
    // differ only by the stripes' blend (35% towards magenta or grey).
    DisplayImage stub = readPng((dir / "stub.png").string()), done = readPng((dir / "done.png").string());
    int striped = 0, frame = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < stub.width; ++x) {
            ++frame;
            int most = 0;
            for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(stub.at(x, y)[c]) - int(done.at(x, y)[c])));
            striped += most > 8;
        }
    EXPECT_GT(striped, frame / 2) << "no stripes in the frame of the environment picture with 11's stub";
}

// Never negative light (issue 34): a dim sky with one sun pixel, its value
// swept up to the documented maximum of a map's value (1e15, docs/scene-format.md)
// at the largest intensity (1e6). SH9 irradiance rings below zero opposite
// such a sun (with 1e4: 54 pixels below 0 before the clamp; seen failing
// without it); the GL picture and the CPU reference must both give finite,
// non-negative radiance everywhere, with the spheres' occlusion compiled in
// (three spheres) and without it (one).
TEST(EnvironmentPicture, NoNegativeOrNonFiniteLightAtAnySunIntensity) {
    const fs::path dir = test::freshTempDir("environment-sun-sweep");
    for (double sun : {1e2, 1e4, 1e6, 1e10, 1e15}) {
        RadianceImage map;
        map.width = 16;
        map.height = 8;
        map.rgb.assign(16 * 8 * 3, 0.05f);
        for (int c = 0; c < 3; ++c) map.at(5, 2)[c] = float(sun);
        writePfm((dir / "sun.pfm").string(), map);
        for (const char* spheres :
             {R"([{"center": [0, 0, 0], "radius": 0.5, "material": {"albedo": [0.8, 0.8, 0.8], "roughness": 0.6, "metallic": 0}}])",
              R"([{"center": [-0.5, 0, 0], "radius": 0.45, "material": {"albedo": [0.8, 0.8, 0.8], "roughness": 0.9, "metallic": 0}},
                  {"center": [0.5, 0, 0], "radius": 0.45, "material": {"albedo": [0.9, 0.6, 0.3], "roughness": 0.3, "metallic": 1}},
                  {"center": [0, -100.5, 0], "radius": 100, "material": {"albedo": [0.5, 0.5, 0.5], "roughness": 0.8, "metallic": 0}}])"}) {
            for (double intensity : {1.0, 1e6}) {
                const std::string json =
                    std::string(R"({"camera": {"position": [0, 0.4, 3], "target": [0, 0, 0], "fov_y": 50},
                    "render": {"width": 32, "height": 24, "max_bounces": 1, "ambient": 0},
                    "environment": {"file": "sun.pfm", "intensity": )") +
                    std::to_string(intensity) + R"(, "rotation": 40}, "lights": [], "spheres": )" + spheres + "}";
                Scene s = parseScene(json, (dir / "scene.json").string()).scene;
                ref::EnvironmentOptions few;
                few.samples = 16;
                const Rendering pictures[2] = {test::renderGl(s), ref::renderCpu(s, 0, few)};
                for (int k = 0; k < 2; ++k) {
                    const Rendering& r = pictures[k];
                    const char* which = k == 0 ? "GL" : "CPU";
                    int negative = 0, nonFinite = 0;
                    float lowest = 0.0f;
                    for (float v : r.radiance.rgb) {
                        nonFinite += !std::isfinite(v);
                        negative += v < 0.0f;
                        lowest = std::min(lowest, v);
                    }
                    EXPECT_EQ(negative, 0) << which << ": sun " << sun << " intensity " << intensity << ", lowest "
                                           << lowest << "\n" << json;
                    EXPECT_EQ(nonFinite, 0) << which << ": sun " << sun << " intensity " << intensity << "\n" << json;
                }
            }
        }
    }
}

// `raylab render --cpu --samples N --seed S` (issue 34): the environment
// integral's directions and seed, apart from the pixel filter's --spp. The
// same seed gives the same bytes, another seed another picture, and either
// option without --cpu is one line and exit 1.
TEST(EnvironmentPicture, CpuSamplesAndSeedAreOptions) {
    const fs::path dir = test::freshTempDir("environment-cpu-options");
    const std::string scene = (sourceRoot() / "scenes/environments/sky-spheres.json").string();
    auto render = [&](const std::string& name, const std::string& options) {
        auto r = test::runRaylab("render " + scene + " --cpu --size 16x12 " + options + " -o " + (dir / name).string());
        EXPECT_EQ(r.status, 0) << r.output;
        return test::readText(dir / name);
    };
    const std::string a = render("a.png", "--samples 8 --seed 5"), b = render("b.png", "--samples 8 --seed 5");
    const std::string c = render("c.png", "--samples 8 --seed 6");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    for (const char* option : {"--samples 8", "--seed 2"}) {
        auto r = test::runRaylab("render " + scene + " --size 16x12 " + option + " -o " + (dir / "d.png").string());
        EXPECT_EQ(r.status, 1) << option;
        EXPECT_NE(r.output.find("add --cpu"), std::string::npos) << r.output;
    }
}
