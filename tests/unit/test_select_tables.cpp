// The generated shaders' per-sphere tables of few values as functions of
// selects (bench/expert_scene.h, selectTables): what is rewritten, what is
// left, and that every use follows its table.
#include "bench/expert_scene.h"

#include <gtest/gtest.h>

using rl::scene_facts::selectTables;

TEST(SelectTables, FewValuesBecomeSelectsWithTheMostFrequentUntested) {
    const std::string text =
        "const float SIR[4] = float[4](2.0, 2.0, 0.5, 2.0);\n"
        "const vec3 SC[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0));\n"
        "    vec3 no = (p - SC[id]) * SIR[id];\n";
    const std::string out = selectTables(text);
    EXPECT_NE(out.find("float SIR(int i) { return (i == 2) ? 0.5 : 2.0; }"), std::string::npos) << out;
    EXPECT_NE(out.find("vec3 SC(int i) { return (i == 1) ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0); }"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("vec3 no = (p - SC(id)) * SIR(id);"), std::string::npos) << out;
    EXPECT_EQ(out.find('['), std::string::npos) << out;
}

TEST(SelectTables, ManyValuesStayArraysAndOtherNamesAreUntouched) {
    std::string many = "const float SA2[10] = float[10](";
    for (int i = 0; i < 10; ++i) many += (i ? ", " : "") + std::to_string(i) + ".5";
    many += ");\n";
    const std::string text = many +
                             "const uint M0_0[2] = uint[2](3u, 3u);\n"
                             "uniform float XM0_0[2];\n"
                             "    a = SA2[k] + float(M0_0[id]) + XM0_0[id] + M0_0[k + 1];\n";
    const std::string out = selectTables(text);
    EXPECT_NE(out.find(many), std::string::npos) << out;  // 10 values > kSelectTableMax
    EXPECT_NE(out.find("uint M0_0(int i) { return 3u; }"), std::string::npos) << out;
    EXPECT_NE(out.find("a = SA2[k] + float(M0_0(id)) + XM0_0[id] + M0_0(k + 1);"), std::string::npos) << out;
}

TEST(SelectTables, TiesAndSeveralIdsPerValue) {
    const std::string out = selectTables("const int T[5] = int[5](7, 8, 7, 8, 9);\n    x = T[j];\n");
    // 7 and 8 twice each: the later one (8) is the default; 7 is tested by both its ids.
    EXPECT_NE(out.find("int T(int i) { return (i == 0 || i == 2) ? 7 : (i == 4) ? 9 : 8; }"), std::string::npos) << out;
    EXPECT_NE(out.find("x = T(j);"), std::string::npos) << out;
}
