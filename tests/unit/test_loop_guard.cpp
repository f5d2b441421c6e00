// The loop guard (app/shader/loop_guard.h): every loop of an exercise file
// gets the guard in its condition, on the same line; what cannot be bounded
// is refused with the file and line.
#include "core/error.h"
#include "core/paths.h"
#include "shader/loop_guard.h"
#include "shader/shader_library.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

using namespace rl;

namespace {

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

std::string refusal(const std::string& text) {
    try {
        guardLoops(text, "student/05-ggx.glsl", 1);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(LoopGuard, EveryKindOfLoopIsGuardedOnItsOwnLine) {
    const std::string text =
        "float f(float x) {\n"                                   // 1
        "    for (int i = 0; i < 4; ++i) x += 1.0;\n"           // 2
        "    for (;;) { if (x > 9.0) break; x += 1.0; }\n"      // 3
        "    while (x < 100.0)\n"                               // 4
        "        x *= 2.0;\n"                                   // 5
        "    do {\n"                                            // 6
        "        x -= 1.0;  // while (true) in a comment\n"     // 7
        "    } while (x > 3.0 &&\n"                             // 8
        "             x < 1000.0);\n"                           // 9
        "    /* for (;;) {} */ return x;\n"                     // 10
        "}\n";
    GuardedSource g = guardLoops(text, "05-ggx.glsl", 7);
    EXPECT_EQ(lines(g.text), lines(text));
    EXPECT_EQ(g.loopLines, (std::vector<int>{2, 3, 4, 6}));  // the do-while is where its `do` is
    EXPECT_NE(g.text.find("for (int i = 0; rl_loop((i < 4), 7); ++i)"), std::string::npos) << g.text;
    // A loop whose body is a block tests its condition at the end (rotated).
    EXPECT_NE(g.text.find("{ ; if (rl_loop(true, 8)) do { if (x > 9.0) break; x += 1.0; } while (rl_loop(true, 8)); }"),
              std::string::npos)
        << g.text;
    EXPECT_NE(g.text.find("while (rl_loop((x < 100.0), 9))"), std::string::npos) << g.text;
    EXPECT_NE(g.text.find("} while (rl_loop((x > 3.0 &&\n             x < 1000.0), 10));"), std::string::npos) << g.text;
    EXPECT_NE(g.text.find("// while (true) in a comment"), std::string::npos);
    EXPECT_NE(g.text.find("/* for (;;) {} */"), std::string::npos);
    // A file without loops is unchanged, byte for byte.
    const std::string plain = "float g(float x) { return x * (x + 1.0); }\n// for (;;)\n";
    EXPECT_EQ(guardLoops(plain, "a.glsl", 1).text, plain);
    // Names that contain the keywords are no loops.
    const std::string names = "float format(float whiley) { float do_it = whiley; return do_it; }\n";
    EXPECT_EQ(guardLoops(names, "a.glsl", 1).text, names);
}

TEST(LoopGuard, RefusesWhatItCannotBound) {
    EXPECT_EQ(refusal("#define FOREVER while (true)\nvoid f() { FOREVER {} }\n").substr(0, 31),
              "student/05-ggx.glsl:1: error: a")
        << refusal("#define FOREVER while (true)\n");
    EXPECT_NE(refusal("#define LOOP(n) \\\n  for (int i = 0; i < n; ++i)\n").find("05-ggx.glsl:2: error: a loop inside a #define"),
              std::string::npos);
    EXPECT_NE(refusal("void f() {\n  float b = 1.0;\n  while (bool c = b > 0.0) b -= 1.0;\n}\n")
                  .find("05-ggx.glsl:3: error: a loop condition that declares a variable"),
              std::string::npos);
    EXPECT_NE(refusal("void f() {\n  float big[100000000];\n}\n").find("05-ggx.glsl:2: error: an array of 100000000 elements"),
              std::string::npos);
    EXPECT_EQ(refusal("void f() {\n  float small[16];\n  vec3 v[3] = vec3[3](vec3(0.0), vec3(1.0), vec3(2.0));\n}\n"), "");
    // A syntax error is the driver's to report: left as it is.
    EXPECT_EQ(refusal("void f() { for (int i = 0; i < 3) {} while x {} }\n"), "");
}

// Issue 22: sizes behind a constant, a macro, a product or a struct were not
// folded, so 50,000,000 floats reached the compiler (60 s, 3.1 GB per check).
TEST(LoopGuard, ArraySizesAreBoundedAfterFoldingConstantsAndMacros) {
    auto refusedAt = [](const std::string& text) {
        const std::string r = refusal(text);
        return r.empty() ? std::string("(accepted)") : r.substr(0, r.find(": error: ") + 9);
    };
    EXPECT_EQ(refusedAt("const int N = 50000000;\nvoid f() {\n  float big[N];\n}\n"), "student/05-ggx.glsl:3: error: ");
    EXPECT_EQ(refusedAt("#define N 50000000\nvoid f() {\n  float big[N];\n}\n"), "student/05-ggx.glsl:3: error: ");
    EXPECT_EQ(refusedAt("void f() {\n  float big[7000 * 7000];\n}\n"), "student/05-ggx.glsl:2: error: ");
    EXPECT_EQ(refusedAt("const int A = 7000;\n#define B (A * 2 + 1)\nvoid f() {\n  float big[B];\n}\n"),
              "student/05-ggx.glsl:4: error: ");
    EXPECT_EQ(refusedAt("void f() {\n  float grid[100][100];\n}\n"), "student/05-ggx.glsl:2: error: ");
    // Arrays inside a struct: the struct's members add up, an array of structs multiplies.
    EXPECT_EQ(refusedAt("struct S {\n  float a[4000];\n  float b[4000];\n};\n"), "student/05-ggx.glsl:1: error: ");
    EXPECT_EQ(refusedAt("struct S { float a[64]; vec3 p; };\nvoid f() {\n  S many[1000];\n}\n"),
              "student/05-ggx.glsl:3: error: ");
    EXPECT_EQ(refusedAt("void f() {\n  struct T { float a[3000]; float b[3000]; } t;\n}\n"),
              "student/05-ggx.glsl:2: error: ");
    EXPECT_NE(refusal("const int N = 50000000;\nvoid f() {\n  float big[N];\n}\n").find("[N] of 50000000 elements"),
              std::string::npos)
        << refusal("const int N = 50000000;\nvoid f() {\n  float big[N];\n}\n");
    // What a finished exercise writes stays accepted: small constants, indexes, function-like macros.
    EXPECT_EQ(refusedAt("const int MAX_LIGHTS = 8;\n#define SPHERES 64\nstruct Hit { float t; vec3 p; vec3 n; };\n"
                        "void f(int i) {\n  Hit hits[SPHERES];\n  vec3 l[MAX_LIGHTS * 2];\n  float x = l[MAX_LIGHTS - 1].x;\n"
                        "  mat3 m; float y = m[2][1];\n  float g[64][64];\n}\n#define SQ(a) ((a) * (a))\n"),
              "(accepted)");
    EXPECT_EQ(refusedAt("void f(int n) {\n  float a[n * 100000];\n}\n"), "(accepted)") << "not constant: the driver's to report";
}

TEST(LoopGuard, TheShaderLimitIsTheHostLimit) {
    std::ifstream in(shadersDir() / "loop_guard.glsl");
    std::stringstream text;
    text << in.rdbuf();
    std::smatch m;
    const std::string s = text.str();
    ASSERT_TRUE(std::regex_search(s, m, std::regex(R"(const int RL_LOOP_LIMIT = (\d+);)")));
    EXPECT_EQ(std::stoi(m[1]), kLoopLimit);
    ASSERT_TRUE(std::regex_search(s, m, std::regex(R"(const int RL_LOOP_TOTAL_LIMIT = (\d+);)")));
    EXPECT_EQ(std::stoi(m[1]), kLoopTotalLimit);
    ASSERT_TRUE(std::regex_search(s, m, std::regex(R"(const int RL_LOOP_TOTAL_FLAG = (\d+);)")));
    EXPECT_EQ(std::stoi(m[1]), kLoopTotalFlag);
}

// Issue 22: the message says which bound a loop met, and what was counted.
TEST(LoopGuard, TheTimeoutSaysWhatWasMeasured) {
    const std::vector<SourceLocation> loops = {{"/x/student/10-display.glsl", 24}};
    const std::string one = loopTimeoutMessage(loops, 1, "for one input of toneMap");
    EXPECT_EQ(one.rfind("a loop in 10-display.glsl:24 ran more than 16384 iterations for one input of toneMap in one run, "
                        "without its condition becoming false: on a GPU",
                        0),
              0u)
        << one;
    const std::string total = loopTimeoutMessage(loops, kLoopTotalFlag + 1, "in one pixel");
    EXPECT_EQ(total.rfind("the loops of the exercise files ran more than 60000 iterations in all in one pixel, the last "
                          "one tested being the loop in 10-display.glsl:24",
                          0),
              0u)
        << total;
}

TEST(LoopGuard, TrippedLoopIsTheLowestIdMarked) {
    EXPECT_EQ(trippedLoop({1.0f, 0.0f, 1.0f}), 0);
    EXPECT_EQ(trippedLoop({1.0f, -3.0f, -2.0f, 1.0f}), 2);
    EXPECT_EQ(trippedLoop({-1.0e30f}), 0);  // NOT_STARTED is no loop
}

TEST(LoopGuard, TheAssemblerGuardsExerciseFilesOnlyAndKeepsTheAuthorsLines) {
    AssembledSource a = assembleShader("main.frag", Implementation{solutionsDir(), {}}, {});
    // The solutions' one loop (09's bounce loop) counts up to maxBounces():
    // rotated and counted, with no guard; no framework file is rewritten.
    EXPECT_TRUE(a.loops.empty());
    for (const SourceFile& f : a.sources) EXPECT_EQ(f.exercise, !f.guarded.empty()) << f.shown;
    // Its header's line and its body's closing line, each the author's.
    std::vector<std::string> authors;
    for (int k = 1; k <= int(a.lines.size()); ++k) {
        if (a.lineText(k).find("rl_counted(") == std::string::npos || a.lines[std::size_t(k) - 1].file.find("shaders/") != std::string::npos)
            continue;
        EXPECT_NE(a.lines[std::size_t(k) - 1].file.find("09-reflections.glsl"), std::string::npos);
        authors.push_back(a.authorLine(k));
    }
    ASSERT_EQ(authors.size(), 2u);
    EXPECT_NE(authors[0].find("for (int bounce = 0; bounce <= maxBounces(); ++bounce)"), std::string::npos) << authors[0];
    EXPECT_EQ(authors[1], "    }");
}

// A loop whose body is a block tests its condition at the end: the same
// tests in the same order, a `continue` going through the step. A counter
// up to a small bound (or maxBounces()) that the body leaves alone needs no
// guard, only its count (rl_counted); anything else keeps its guard.
TEST(LoopGuard, LoopsWithBlocksAreRotatedAndBoundedCountersUnguarded) {
    auto rewritten = [](const std::string& body) { return guardLoops(body, "09-reflections.glsl", 1); };
    GuardedSource w = rewritten("void f(float x) {\n  while (x < 5.0) { x += 1.0; }\n}\n");
    EXPECT_NE(w.text.find("if (rl_loop((x < 5.0), 1)) do { x += 1.0; } while (rl_loop((x < 5.0), 1));"), std::string::npos)
        << w.text;
    GuardedSource n = rewritten("void f(int n) {\n  for (int i = 0; i < n; ++i) { n -= 0; }\n}\n");
    EXPECT_NE(n.text.find("{ int i = 0; if (rl_loop(( i < n), 1)) do { n -= 0; } while ((( ++i), rl_loop(( i < n), 1))); }"),
              std::string::npos)
        << n.text;
    const std::string bounded = "void f() {\n  for (int b = 0; b <= maxBounces(); ++b) { g(1.0); }\n}\n";
    GuardedSource c = rewritten(bounded);
    EXPECT_TRUE(c.loopLines.empty());
    EXPECT_NE(c.text.find("{ int b = 0; if (rl_counted( b <= maxBounces())) do { g(1.0); } while ((( ++b), rl_counted( b <= maxBounces()))); }"),
              std::string::npos)
        << c.text;
    EXPECT_TRUE(rewritten("void f() {\n  for (int i = 0; i < 64; i++) { }\n}\n").loopLines.empty());
    // Guarded: a bound too large or not a constant, a counter the body
    // changes, hands on or declares again, a loop inside, a condition or a
    // step on two lines.
    for (const char* loop : {"for (int i = 0; i < 65; ++i) { }", "for (int i = 0; i < n; ++i) { }",
                             "for (int i = 0; i < 8; ++i) { i += 2; }", "for (int i = 0; i < 8; ++i) { i--; }",
                             "for (int i = 0; i < 8; ++i) { h(x, i); }", "for (int i = 0; i < 8; ++i) { int i = 1; }",
                             "for (int i = 0; i < 8; ++i) { for (;;) { break; } }", "for (int i = 0; i < 8; i += 2) { }",
                             "for (int i = 0;\n i < 8; ++i) { }"}) {
        GuardedSource g = rewritten(std::string("void f(int n, float x) {\n  ") + loop + "\n}\n");
        EXPECT_FALSE(g.loopLines.empty()) << loop;
        EXPECT_EQ(lines(g.text), lines(std::string("void f(int n, float x) {\n  ") + loop + "\n}\n")) << loop;
    }
}
