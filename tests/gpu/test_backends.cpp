// Headless backends: EGL and OSMesa both give a 3.3 core context, and render
// the same scene identically (or within the core budget).
#include "core/error.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

using namespace rl;

TEST(Backends, EglGivesACoreContext) {
    auto context = createHeadlessContext(Backend::Egl);
    EXPECT_NE(context->description().find("EGL"), std::string::npos) << context->description();
}

#ifdef RAYLAB_WITH_OSMESA
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
        EXPECT_STREQ(e.what(), "--backend: unknown backend 'vulkan' (expected auto, egl or osmesa)");
    }
}

TEST(Backends, NoBackendAvailableSaysWhatWasTried) {
    // An EGL vendor file that does not exist leaves libglvnd without a driver.
    auto r = test::runRaylab("render -o /tmp/raylab_nobackend.png --backend egl",
                             "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("no OpenGL 3.3 context could be created (tried EGL:"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}
