// Runaway loops end the same way on every machine (app/shader/loop_guard.h):
// a loop that would never finish on a GPU is TIMEOUT with its file and line,
// in every run, never a picture that llvmpipe's own loop cap made plausible.
// Each fixture is the 05-ggx solution with one loop added at the top of D_GGX.
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace rl;

namespace {

struct Runaway {
    const char* name;
    const char* loop;  // put on line 9 of 05-ggx.glsl, the first line of D_GGX's body
};

// The solution's line 8 is `float D_GGX(vec3 n, vec3 h, float alpha) {`.
const Runaway kRunaways[] = {
    // Constant true, no way out.
    {"constant_true", "    float spin = 0.5; while (true) { spin = spin * 0.5 + 0.25; }"},
    // A bound that exists but is a billion iterations away, read from a uniform.
    {"huge_uniform_bound",
     "    float spin = 0.0; for (int i = 0; i < 1000000000 + maxBounces(); ++i) { spin += 1e-9; }"},
    // A break whose condition is never met.
    {"break_never_met", "    float spin = 1.0; while (true) { spin += 1.0; if (spin < 0.0) break; }"},
};

void PrintTo(const Runaway& r, std::ostream* os) { *os << r.name; }

fs::path runawayFile(const Runaway& r) {
    std::string text = test::readText(solutionsDir() / "05-ggx.glsl");
    const std::string head = "float D_GGX(vec3 n, vec3 h, float alpha) {\n";
    auto pos = text.find(head);
    EXPECT_NE(pos, std::string::npos);
    text.insert(pos + head.size(), std::string(r.loop) + "\n    alpha += 1e-30 * spin;\n");
    fs::path file = test::freshTempDir(std::string("runaway_") + r.name) / "05-ggx.glsl";
    test::writeText(file, text);
    return file;
}

}  // namespace

class RunawayLoops : public ::testing::TestWithParam<Runaway> {};

TEST_P(RunawayLoops, AreTimeoutWithTheLoopsLineInEveryRun) {
    const fs::path file = runawayFile(GetParam());
    std::string first;
    for (int run = 0; run < 2; ++run) {
        auto r = test::runRaylab("check --exercise 5 --file " + file.string() + " --output " +
                                 test::freshTempDir("runaway_out").string());
        EXPECT_EQ(r.status, 1) << r.output;
        // The verdict and the reason: the student's file and the loop's line (9).
        EXPECT_NE(r.output.find("05-ggx            TIMEOUT       a loop in 05-ggx.glsl:9 ran more than 16384 "
                                "iterations"),
                  std::string::npos)
            << r.output;
        // The same in every run (the last line says how long the run took).
        const std::string verdict = r.output.substr(0, r.output.rfind("exercises pass"));
        if (run == 0) first = verdict;
        else EXPECT_EQ(verdict, first);
    }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, RunawayLoops, ::testing::ValuesIn(kRunaways),
                         [](const ::testing::TestParamInfo<Runaway>& info) { return std::string(info.param.name); });

// Issue 22: the guard counted every guarded iteration of a pixel together, so
// a loop of 7000 iterations in toneMap, bounded and finished in every call,
// was TIMEOUT ("needs a bound that it reaches"). It counts per run of a loop now.
TEST(RunawayLoops, ABoundedLoopOf7000InToneMapPasses) {
    std::string text = test::readText(solutionsDir() / "10-display.glsl");
    const std::string head = "vec3 toneMap(vec3 c, int op) {\n";
    auto pos = text.find(head);
    ASSERT_NE(pos, std::string::npos);
    text.insert(pos + head.size(), "    float spin = 0.0;\n    for (int i = 0; i < 7000; i++) { spin += 1.0; }\n"
                                   "    c += 1e-30 * spin;\n");
    const fs::path file = test::freshTempDir("bounded_7000") / "10-display.glsl";
    test::writeText(file, text);
    auto r = test::runRaylab("check --exercise 10 --file " + file.string() + " --output " +
                             test::freshTempDir("bounded_7000_out").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("10-display        PASS"), std::string::npos) << r.output;
}

// A bounded loop run too often in one pixel (5000 iterations in D_GGX, which
// runs for every light, bounce and sample) meets the total bound, and the
// message says so rather than blaming one run.
TEST(RunawayLoops, ALoopRunTooOftenMeetsTheTotalAndSaysSo) {
    Runaway often{"often", "    float spin = 0.0; for (int i = 0; i < 5000; ++i) { spin += 1.0; }"};
    const fs::path file = runawayFile(often);
    auto r = test::runRaylab("check --exercise 5 --file " + file.string() + " --output " +
                             test::freshTempDir("often_out").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("05-ggx            TIMEOUT       the loops of the exercise files ran more than 60000 "
                            "iterations in all"),
              std::string::npos)
        << r.output;
}

TEST(RunawayLoops, ALoopThatEndsInTimePasses) {
    // The guard only ends loops that run away: a bounded loop of 64
    // iterations per call (about 20,000 per pixel would trip it) changes nothing.
    Runaway bounded{"bounded", "    float spin = 0.0; for (int i = 0; i < 64; ++i) { spin += 1.0; }"};
    const fs::path file = runawayFile(bounded);
    auto r = test::runRaylab("check --exercise 5 --file " + file.string() + " --output " +
                             test::freshTempDir("bounded_out").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("05-ggx            PASS"), std::string::npos) << r.output;
}

TEST(RunawayLoops, AnIntConditionIsExplainedNotBlamedOnTheGuard) {
    Runaway intCondition{"int_condition", "    float spin = 0.0; while (1) { spin += 1.0; break; }"};
    const fs::path file = runawayFile(intCondition);
    auto r = test::runRaylab("check --exercise 5 --file " + file.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("COMPILE ERROR"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("05-ggx.glsl:9: error: a loop's condition must be a bool"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("    float spin = 0.0; while (1) {"), std::string::npos) << r.output;  // the author's line
    EXPECT_EQ(r.output.find("rl_loop"), std::string::npos) << r.output;
}

TEST(RunawayLoops, AHugeArrayIsRefusedWithItsOwnReason) {
    Runaway array{"huge_array", "    float spin = 0.0; float big[50000000]; big[7] = 1.0; spin = big[7];"};
    const fs::path file = runawayFile(array);
    auto r = test::runRaylab("check --exercise 5 --file " + file.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("05-ggx.glsl:9: error: an array of 50000000 elements is more memory than a GPU gives one "
                            "pixel"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("a loop"), std::string::npos) << r.output;
}

TEST(RunawayLoops, AMacroBombIsRefusedTheSameInEveryRun) {
    // Twenty doublings: A20 is a million tokens. Refused before the driver's
    // preprocessor sees it, so the verdict does not depend on the machine.
    std::string text = test::readText(solutionsDir() / "05-ggx.glsl") + "#define A0 1.0\n";
    for (int k = 1; k <= 20; ++k)
        text += "#define A" + std::to_string(k) + " A" + std::to_string(k - 1) + " + A" + std::to_string(k - 1) + "\n";
    text += "float bomb() { return A20; }\n";
    fs::path file = test::freshTempDir("macro_bomb") / "05-ggx.glsl";
    test::writeText(file, text);
    std::string first;
    for (int run = 0; run < 2; ++run) {
        auto r = test::runRaylab("check --exercise 5 --file " + file.string());
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_NE(r.output.find("05-ggx.glsl:35: error: the macro A20 expands to more than a million tokens"),
                  std::string::npos)
            << r.output;
        const std::string verdict = r.output.substr(0, r.output.rfind("exercises pass"));
        if (run == 0) first = verdict;
        else EXPECT_EQ(verdict, first);
    }
}
