// The bench's environment sweep (app/bench/environment_sweep.h, issue 24),
// run as documented in docs/performance.md but tiny: its rows, its exact
// references, its own Markdown section, and the default approximation held
// to the error budget written beside the table. Times are never asserted.
#include "bench/bench.h"
#include "bench/bench_test_support.h"
#include "bench/environment_sweep.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/define_table.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "shader/shader_library.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace rl;
using namespace rl::bench;
namespace fs = std::filesystem;
using rl::test::readCsv;

namespace {

std::string environmentScene(const char* name) {
    return (scenesDir() / "environments" / (std::string(name) + ".json")).string();
}

}  // namespace

// Every setting of the sweep is a row of the environment scene, none of the
// scene without an environment; the exact reference without visibility is a
// row of its own whose error against itself is 0 and against the reference
// with visibility is not (the spheres shadow the ground: contact occlusion).
TEST(EnvironmentSweep, RowsReferencesAndTheirOwnMarkdownSection) {
    fs::path dir = test::freshTempDir("bench_environment");
    const fs::path csv = dir / "env.csv", doc = dir / "doc.md";
    test::writeText(doc, "# Page\n\n<!-- bench:begin -->\nother table\n<!-- bench:end -->\n\n"
                         "<!-- bench-environment:begin -->\nold\n<!-- bench-environment:end -->\n\nAfter.\n");
    auto r = test::runRaylab("bench " + environmentScene("sky-spheres") + " " + (scenesDir() / "lecture.json").string() +
                             " --sweeps environment --size 24x16 --warmup 0 --frames 1 --environment-samples 64"
                             " --csv " + csv.string() + " --markdown " + doc.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const auto rows = readCsv(test::readText(csv));
    ASSERT_EQ(rows.size(), environmentSweep().size() + 1) << r.output;  // the lecture scene has no environment
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("scene"), "sky-spheres");
        EXPECT_EQ(row.at("sweep"), "environment");
    }
    EXPECT_EQ(rows.front().at("variant"), "env:default");
    const auto& exact = rows.back();
    EXPECT_EQ(exact.at("variant"), "exact:no-V");
    ASSERT_EQ(exact.at("skipped"), "0") << exact.at("note");
    EXPECT_EQ(exact.at("mode"), "reference");
    EXPECT_EQ(exact.at("pareto"), "0");  // a CPU time is not on the GL frames' front
    EXPECT_EQ(exact.at("reference_samples"), "64");
    EXPECT_EQ(std::stod(exact.at("err_mean_lsb_no_v")), 0.0);
    EXPECT_GT(std::stod(exact.at("err_mean_lsb")), 1.0);
    EXPECT_GT(std::stod(exact.at("reference_noise_lsb")), 0.0);  // 64 samples are noisy, and the run says so

    // The irradiance maps (RL_ENV_IRRADIANCE_MAP, 16x8 to 128x64) are drawn,
    // not skipped, with finite errors; the largest is at least as close to
    // the exact reference without visibility as SH9 (the default): a 128 x 64
    // map of E(n) in double resolves the sun's and the panels' lobes that nine
    // coefficients blur. Measured at 48x36 and 256 samples (docs/performance.md):
    // sky 1.530 against 1.829 LSB, studio 2.303 against 2.449; here at 24x16 and
    // 64 samples 2.090 against 2.224 (printed below): both rows are compared
    // with the same fixed-seed reference, so its noise moves them alike and
    // the comparison is deterministic on a given driver.
    std::map<std::string, std::map<std::string, std::string>> byVariant;
    for (const auto& row : rows) byVariant[row.at("variant")] = row;
    for (int n : kIrradianceMapWidths) {
        const std::string name = "env:irradiance-map=" + std::to_string(n) + "x" + std::to_string(n / 2);
        ASSERT_TRUE(byVariant.count(name)) << name;
        const auto& row = byVariant.at(name);
        EXPECT_EQ(row.at("skipped"), "0") << name << ": " << row.at("note");
        EXPECT_EQ(row.at("non_finite"), "0") << name;
        EXPECT_TRUE(std::isfinite(std::stod(row.at("err_mean_lsb")))) << name;
        EXPECT_TRUE(std::isfinite(std::stod(row.at("err_mean_lsb_no_v")))) << name;
    }
    // Every row but env:occlusion=none is shadowed alike (issue 34), so their
    // errors WITH visibility compare the irradiance: the finest map is at
    // least as close to the truth as the coarsest.
    const double map16 = std::stod(byVariant.at("env:irradiance-map=16x8").at("err_mean_lsb"));
    const double map128 = std::stod(byVariant.at("env:irradiance-map=128x64").at("err_mean_lsb"));
    const double sh9 = std::stod(byVariant.at("env:default").at("err_mean_lsb"));
    const double none = std::stod(byVariant.at("env:occlusion=none").at("err_mean_lsb"));
    std::printf("with V: SH9 and the sun %.3f LSB, irradiance map 16x8 %.3f, 128x64 %.3f LSB; unshadowed %.3f\n", sh9,
                map16, map128, none);
    EXPECT_LE(map128, map16);
    EXPECT_LT(2 * sh9, none);  // the shadows: the unshadowed picture is the one far from the truth

    const std::string text = test::readText(doc);
    EXPECT_NE(text.find("other table"), std::string::npos) << text;  // the other section is kept
    EXPECT_EQ(text.find("\nold\n"), std::string::npos) << text;
    EXPECT_NE(text.find("--sweeps environment"), std::string::npos) << text;
    EXPECT_NE(text.find("exact:no-V"), std::string::npos) << text;
    EXPECT_NE(text.find("noise"), std::string::npos) << text;
    EXPECT_NE(text.find("<!-- bench-environment:end -->\n\nAfter.\n"), std::string::npos) << text;
}

// The default approximation (shadowed by the spheres, issue 34) on both
// shipped environment scenes, small (48x36) and against references of 256
// samples per strategy, within the budget that
// docs/performance.md writes beside the table (environmentBudget()): the
// picture `raylab render` draws (Purpose::Picture) and the bench's exact
// references, without the sweep's other rows (each its own program: the
// whole sweep is EnvironmentSweep's above, at a smaller size). The
// reference's own noise at this sample count is part of the measured error,
// which makes the test stricter, not looser.
TEST(EnvironmentBudget, TheDefaultStaysWithinTheBudget) {
    test::ensureHeadlessContext();
    std::ostringstream log;
    for (const char* name : {"sky-spheres", "studio-spheres"}) {
        SCOPED_TRACE(name);
        Scene scene = loadSceneFile(environmentScene(name)).scene;
        scene.render.width = 48;
        scene.render.height = 36;
        const ExactReferences exact = exactReferences(scene, 256, log);
        const Implementation impl{solutionsDir(), {}};
        const Rendering got = renderOnce(
            buildPictureProgram(impl, definesFor(scene, implementationFacts(impl), Purpose::Picture)), scene,
            frameFromScene(scene));
        Measurement row, noVisibility;
        row.referenceNoiseLsb = exact.noiseMeanLsb;
        row.referenceNoiseOffFraction = exact.noiseOffFraction;
        row.error = compareRenderings(got, exact.withVisibility);
        row.errorWithoutVisibility = compareRenderings(got, exact.withoutVisibility);
        noVisibility.error = compareRenderings(exact.withoutVisibility, exact.withVisibility);
        std::printf("%s: with V mean %.3f LSB, %.1f%% off (exact:no-V %.3f); reference noise %.3f LSB, %.1f%% off\n",
                    name, row.error.meanLsb, 100 * row.error.offFraction, noVisibility.error.meanLsb,
                    exact.noiseMeanLsb, 100 * exact.noiseOffFraction);
        EXPECT_EQ(row.error.nonFinite, 0);
        const EnvironmentBudgetCheck check = checkEnvironmentBudget(row, noVisibility);
        EXPECT_TRUE(check.mean) << row.error.meanLsb;
        EXPECT_TRUE(check.off) << row.error.offFraction;
        EXPECT_TRUE(check.belowNoVisibility) << row.error.meanLsb << " against " << noVisibility.error.meanLsb;
    }
}

// The budget's third part asks occlusion to buy back most of what leaving
// visibility out costs; where that costs no more than the mean's own budget
// (a few small spheres over a ground: exact:no-V about 1 LSB from the
// truth), there is nothing to buy back and only the mean's bound is asked.
// Before, a default of 0.51 LSB against a no-V of 1.04 was reported as
// not meeting the budget.
TEST(EnvironmentBudget, NothingToBuyBackWhereVisibilityCostsLittle) {
    const EnvironmentBudget& b = environmentBudget();
    Measurement row, noVisibility;
    row.error.meanLsb = 0.51;
    noVisibility.error.meanLsb = 1.04;
    EXPECT_TRUE(checkEnvironmentBudget(row, noVisibility).belowNoVisibility);
    EXPECT_TRUE(checkEnvironmentBudget(row, noVisibility).nothingToBuyBack);
    EXPECT_TRUE(checkEnvironmentBudget(row, noVisibility).meets());
    // Where visibility costs much, the share is asked.
    noVisibility.error.meanLsb = 4 * b.meanLsb;
    row.error.meanLsb = b.noVisibilityShare * noVisibility.error.meanLsb * 1.01;
    EXPECT_FALSE(checkEnvironmentBudget(row, noVisibility).belowNoVisibility);
    EXPECT_FALSE(checkEnvironmentBudget(row, noVisibility).nothingToBuyBack);
    row.error.meanLsb = b.noVisibilityShare * noVisibility.error.meanLsb * 0.99;
    EXPECT_TRUE(checkEnvironmentBudget(row, noVisibility).belowNoVisibility);
}
