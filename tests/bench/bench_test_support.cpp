#include "bench/bench_test_support.h"

#include "core/scene_io.h"
#include "gl/context.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <memory>

namespace rl::test {

void ensureHeadlessContext() {
    static std::unique_ptr<GlContext> context = createHeadlessContext(Backend::Auto);
}

Scene tinyScene(const std::filesystem::path& file) {
    Scene s = loadSceneFile(file.string()).scene;
    s.render.width = 64;
    s.render.height = 48;
    return s;
}

void expectWithinBudget(const Rendering& got, const Rendering& expected, const std::string& what) {
    ImageDiff d = compareRenderings(got, expected);
    SCOPED_TRACE(what + ": " + describe(d));
    EXPECT_LE(d.offFraction, 0.005);
    EXPECT_LT(d.meanLsb, 0.2);
    EXPECT_EQ(d.nonFinite, 0);
}

}  // namespace rl::test
