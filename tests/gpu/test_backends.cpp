// Headless backends: EGL and OSMesa both give a 3.3 core context, and render
// the same scene identically (or within the core budget).
#include "core/error.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

using namespace rl;

#ifdef RAYLAB_WITH_EGL
TEST(Backends, EglGivesACoreContext) {
    auto context = createHeadlessContext(Backend::Egl);
    EXPECT_NE(context->description().find("EGL"), std::string::npos) << context->description();
}
#endif

#if defined(RAYLAB_WITH_OSMESA) && defined(RAYLAB_WITH_EGL)
TEST(Backends, OsMesaGivesACoreContext) {
    auto context = createHeadlessContext(Backend::OsMesa);
    EXPECT_NE(context->description().find("OSMesa"), std::string::npos) << context->description();
}

TEST(Backends, EglAndOsMesaRenderTheSameImage) {
    Scene s = defaultScene();
    s.render.width = 120;
    s.render.height = 90;
    Rendering egl = test::renderGl(s, "egl");
    Rendering osmesa = test::renderGl(s, "osmesa");
    ImageDiff d = compareRenderings(osmesa, egl);
    SCOPED_TRACE(test::describe(d));
    EXPECT_LE(d.offFraction, 0.005);
    EXPECT_LT(d.meanLsb, 0.2);
    EXPECT_EQ(d.nonFinite, 0);
}
#endif

TEST(Backends, UnknownBackendNameIsOneClearError) {
    try {
        parseBackend("vulkan");
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--backend: unknown backend 'vulkan' (expected auto, egl, osmesa or glfw)");
    }
}

#ifdef RAYLAB_WITH_GLFW_CONTEXT
TEST(Backends, HiddenGlfwWindowWithoutAWindowSystemIsOneClearError) {
    auto r = test::runRaylab("render -o /tmp/raylab_noglfw.png --backend glfw", "DISPLAY= WAYLAND_DISPLAY=");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("no OpenGL 3.3 context could be created (tried GLFW: no window system ("),
              std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(Backends, HiddenGlfwWindowUnderXvfbRendersLikeTheDefaultBackend) {
    // The backend of a build without EGL and OSMesa (macOS, Windows): a
    // hidden 3.3 core window, here on a private Xvfb (scripts/setup.sh --window).
    fs::path dir = test::freshTempDir("glfw_backend");
    auto outputs = [&](const std::string& name) {
        return " render --size 96x72 -o " + (dir / (name + ".png")).string() + " --hdr " + (dir / (name + ".pfm")).string();
    };
    // Its own server numbers (from :120), clear of an xvfb-run around the whole suite (from :99).
    auto glfw = test::runShell("xvfb-run -a -n 120 " + std::string(RAYLAB_BINARY) + outputs("glfw") + " --backend glfw");
    ASSERT_EQ(glfw.status, 0) << glfw.output;
    auto other = test::runRaylab(outputs("auto"));
    ASSERT_EQ(other.status, 0) << other.output;
    Rendering a, b;
    a.radiance = readPfm((dir / "glfw.pfm").string());
    a.display = readPng((dir / "glfw.png").string());
    b.radiance = readPfm((dir / "auto.pfm").string());
    b.display = readPng((dir / "auto.png").string());
    ImageDiff d = compareRenderings(a, b);
    SCOPED_TRACE(test::describe(d));
    // The same driver (llvmpipe) through another door: the same picture, within the core budget.
    EXPECT_LE(d.offFraction, 0.005);
    EXPECT_LT(d.meanLsb, 0.2);
    EXPECT_EQ(d.nonFinite, 0);
}
#endif

TEST(Backends, NoBackendAvailableSaysWhatWasTried) {
    // An EGL vendor file that does not exist leaves libglvnd without a driver.
    auto r = test::runRaylab("render -o /tmp/raylab_nobackend.png --backend egl",
                             "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("no OpenGL 3.3 context could be created (tried EGL:"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}
