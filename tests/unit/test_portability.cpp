// The fix a portability error spells out, from Mesa's GLSL ES 3.00 message
// and the student's line (shader/portability.h). The messages are Mesa's
// own, copied from `#version 300 es` compiles of these lines.
#include "shader/portability.h"

#include <gtest/gtest.h>

using namespace rl;

TEST(Portability, PowWithAnIntExponent) {
    std::string line = "    return F0 + (1.0 - F0) * pow(m, 5);";
    EXPECT_EQ(explainPortability("no matching function for call to `pow(float, int)'; candidates are:", line),
              "pow(float, int) does not exist in GLSL ES: write `pow(m, 5.0)`");
}

TEST(Portability, ClampWithAnIntBound) {
    std::string line = "    float r = clamp(roughness, 0.045, 1);";
    EXPECT_EQ(explainPortability("no matching function for call to `clamp(float, float, int)'; candidates are:", line),
              "clamp(float, float, int) does not exist in GLSL ES: write `clamp(roughness, 0.045, 1.0)`");
}

TEST(Portability, AnIntVariableInACallIsConverted) {
    std::string line = "    float x = max(n, 0.5) * 2.0;";
    EXPECT_EQ(explainPortability("no matching function for call to `max(int, float)'; candidates are:", line),
              "max(int, float) does not exist in GLSL ES: write `max(float(n), 0.5)`");
}

TEST(Portability, IntInFloatArithmetic) {
    std::string line = "    return albedo / PI * 1;";
    EXPECT_EQ(explainPortability("could not implicitly convert operands to arithmetic operator", line),
              "an int in float arithmetic: write `return albedo / PI * 1.0;`");
}

TEST(Portability, FloatComparedWithAnInt) {
    std::string line = "    if (NoL == 0) return vec3(0.0);";
    EXPECT_EQ(explainPortability("operands of `==' must have the same type", line),
              "`==` between a float and an int: write `if (NoL == 0.0) return vec3(0.0);`");
}

TEST(Portability, IntInitialisesAFloat) {
    std::string line = "    float fn = n;";
    EXPECT_EQ(explainPortability("initializer of type int cannot be assigned to variable of type float", line),
              "an int initialises a float: write `float fn = float(n);`");
    std::string literal = "    float k = 2;";
    EXPECT_EQ(explainPortability("initializer of type int cannot be assigned to variable of type float", literal),
              "an int initialises a float: write `float k = 2.0;`");
}

TEST(Portability, TernaryWithAnIntBranch) {
    std::string line = "    float f = c ? 0.045 : 1;";
    EXPECT_EQ(explainPortability("second and third operands of ?: operator must have matching types", line),
              "?: with a float and an int branch: write `float f = c ? 0.045 : 1.0;`");
}

TEST(Portability, IndicesAndIntConstructorsStayInts) {
    std::string line = "    float x = v[i + 1] * float(int(k) + 2) * 3;";
    EXPECT_EQ(explainPortability("could not implicitly convert operands to arithmetic operator", line),
              "an int in float arithmetic: write `float x = v[i + 1] * float(int(k) + 2) * 3.0;`");
}

TEST(Portability, FloatLiteralsAreLeftAlone) {
    // 1e5, 5u, 0x1F and 2.5 are not ints to convert; with nothing to rewrite the fix says what to do.
    std::string line = "    float x = y * 1e5 + 2.5 * float(5u) + i;";
    EXPECT_EQ(explainPortability("could not implicitly convert operands to arithmetic operator", line),
              "an int in float arithmetic: convert the int with float(...)");
}

TEST(Portability, AnUnknownMessageIsPassedOn) {
    EXPECT_EQ(explainPortability("`texture2D' undeclared", "    vec4 c = texture2D(s, uv);"), "`texture2D' undeclared");
}
