// parseDriverLog on logs in the shape each driver family writes them (the
// messages are the ones those compilers print for the same kinds of mistake).
#include "shader/driver_log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using rl::DriverMessage;
using rl::parseDriverLog;

namespace {

void expectMessage(const DriverMessage& m, int line, int column, const std::string& severity, const std::string& text) {
    EXPECT_EQ(m.line, line) << m.text;
    EXPECT_EQ(m.column, column) << m.text;
    EXPECT_EQ(m.severity, severity) << m.text;
    EXPECT_EQ(m.text, text);
}

}  // namespace

TEST(DriverLog, MesaCompileLog) {
    auto m = parseDriverLog(
        "0:5(12): error: `albedoo' undeclared\n"
        "0:5(12): error: operands to arithmetic operators must be numeric\n"
        "0:9(3): warning: `unused' used uninitialized\n");
    ASSERT_EQ(m.size(), 3u);
    expectMessage(m[0], 5, 12, "error", "`albedoo' undeclared");
    expectMessage(m[1], 5, 12, "error", "operands to arithmetic operators must be numeric");
    expectMessage(m[2], 9, 3, "warning", "`unused' used uninitialized");
}

// An unfinished function's own definition is renamed while the host compiles
// its neutral value (shader/readiness.h): the student reads the name they wrote.
TEST(DriverLog, AnUnfinishedFunctionIsQuotedByItsOwnName) {
    auto m = parseDriverLog("0:7(1): error: function `float rl_unfinished_G1_SchlickGGX(float, float)' has static recursion\n");
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].text, "function `float G1_SchlickGGX(float, float)' has static recursion");
}

TEST(DriverLog, MesaPreprocessorErrorIsAnError) {
    auto m = parseDriverLog("0:14(1): preprocessor error: Unterminated comment\n");
    ASSERT_EQ(m.size(), 1u);
    expectMessage(m[0], 14, 1, "error", "Unterminated comment");
}

TEST(DriverLog, MesaLinkLogHasNoLocation) {
    auto m = parseDriverLog(
        "error: fragment shader lacks `main'\n"
        "error: linking with uncompiled/unspecialized shader");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 0, 0, "error", "fragment shader lacks `main'");
    expectMessage(m[1], 0, 0, "error", "linking with uncompiled/unspecialized shader");
}

TEST(DriverLog, NvidiaCompileLogKeepsTheErrorCode) {
    auto m = parseDriverLog(
        "0(12) : error C1008: undefined variable \"albedoo\"\n"
        "0(14) : warning C7533: global variable gl_FragColor is deprecated after version 120\n"
        "0(20) : error C0000: syntax error, unexpected '}', expecting ',' or ';' at token \"}\"\n");
    ASSERT_EQ(m.size(), 3u);
    expectMessage(m[0], 12, 0, "error", "C1008: undefined variable \"albedoo\"");
    expectMessage(m[1], 14, 0, "warning", "C7533: global variable gl_FragColor is deprecated after version 120");
    expectMessage(m[2], 20, 0, "error", "C0000: syntax error, unexpected '}', expecting ',' or ';' at token \"}\"");
}

TEST(DriverLog, NvidiaLinkLogDropsTheStageBanner) {
    auto m = parseDriverLog(
        "Fragment info\n"
        "-------------\n"
        "0(31) : error C1052: function \"shade\" has no body\n"
        "(0) : error C2003: incompatible options for link\n");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 31, 0, "error", "C1052: function \"shade\" has no body");
    expectMessage(m[1], 0, 0, "error", "C2003: incompatible options for link");
}

TEST(DriverLog, AmdLogDropsBannerAndSummary) {
    auto m = parseDriverLog(
        "Fragment shader failed to compile with the following errors:\n"
        "ERROR: 0:12: error(#143) Undeclared identifier: albedoo\n"
        "WARNING: 0:15: warning(#402) Implicit truncation of vector from size: 4 to size: 3\n"
        "ERROR: error(#273) 1 compilation errors.  No code generated\n");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 12, 0, "error", "error(#143) Undeclared identifier: albedoo");
    expectMessage(m[1], 15, 0, "warning", "warning(#402) Implicit truncation of vector from size: 4 to size: 3");
}

TEST(DriverLog, IntelWindowsAndGlslangLogDropsTheSummary) {
    auto m = parseDriverLog(
        "ERROR: 0:12: 'albedoo' : undeclared identifier\n"
        "ERROR: 0:12: 'assign' :  cannot convert from 'const float' to 'out 4-component vector of float'\n"
        "ERROR: 2 compilation errors.  No code generated.\n"
        "\n");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 12, 0, "error", "'albedoo' : undeclared identifier");
    expectMessage(m[1], 12, 0, "error",
                  "'assign' :  cannot convert from 'const float' to 'out 4-component vector of float'");
}

TEST(DriverLog, AppleLog) {
    auto m = parseDriverLog(
        "WARNING: 0:3: Overflow in implicit constant conversion, minimum range for lowp float is (-2,2)\n"
        "ERROR: 0:27: Use of undeclared identifier 'albedoo'\n"
        "ERROR: One or more attached shaders not successfully compiled\n");
    ASSERT_EQ(m.size(), 3u);
    expectMessage(m[0], 3, 0, "warning",
                  "Overflow in implicit constant conversion, minimum range for lowp float is (-2,2)");
    expectMessage(m[1], 27, 0, "error", "Use of undeclared identifier 'albedoo'");
    expectMessage(m[2], 0, 0, "error", "One or more attached shaders not successfully compiled");
}

TEST(DriverLog, GlslangColumnFormAndLinkError) {
    auto m = parseDriverLog(
        "ERROR: 0:8:17: 'roughnes' : undeclared identifier\n"
        "ERROR: Linking fragment stage: Missing entry point: Each stage requires one entry point\n");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 8, 17, "error", "'roughnes' : undeclared identifier");
    expectMessage(m[1], 0, 0, "error", "Linking fragment stage: Missing entry point: Each stage requires one entry point");
}

// ---- Edge cases ------------------------------------------------------------------

TEST(DriverLog, EmptyAndBlankLogsHaveNoMessages) {
    EXPECT_TRUE(parseDriverLog("").empty());
    EXPECT_TRUE(parseDriverLog(std::string(1, '\0')).empty());
    EXPECT_TRUE(parseDriverLog("\n\r\n  \n").empty());
    EXPECT_TRUE(parseDriverLog("No errors.\n").empty());
    EXPECT_TRUE(parseDriverLog("Fragment shader was successfully compiled to run on hardware.\n").empty());
}

TEST(DriverLog, WindowsLineEndingsTrailingBlankLinesAndTheInfoLogNul) {
    // What glGetShaderInfoLog leaves in a buffer of GL_INFO_LOG_LENGTH bytes.
    std::string log = "ERROR: 0:12: 'x' : undeclared identifier\r\n"
                      "WARNING: 0:13: 'y' : unused\r\n"
                      "\r\n\r\n";
    log.push_back('\0');
    auto m = parseDriverLog(log);
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 12, 0, "error", "'x' : undeclared identifier");
    expectMessage(m[1], 13, 0, "warning", "'y' : unused");
}

TEST(DriverLog, LastLineWithoutNewlineIsParsed) {
    auto m = parseDriverLog("0:1(10): error: syntax error, unexpected NEW_IDENTIFIER");
    ASSERT_EQ(m.size(), 1u);
    expectMessage(m[0], 1, 10, "error", "syntax error, unexpected NEW_IDENTIFIER");
}

TEST(DriverLog, UnknownLinesContinueThePreviousMessageOrStandAlone) {
    auto m = parseDriverLog(
        "internal compiler failure in the register allocator\n"
        "0:4(2): error: type mismatch\n"
        "  expected vec3, found vec4\n"
        "note: see the documentation\n");  // "note" is no severity raylab knows: continuation
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 0, 0, "warning", "internal compiler failure in the register allocator");
    expectMessage(m[1], 4, 2, "error", "type mismatch\nexpected vec3, found vec4\nnote: see the documentation");
    auto e = parseDriverLog("Unexpected error in the shader compiler\n");
    ASSERT_EQ(e.size(), 1u);
    expectMessage(e[0], 0, 0, "error", "Unexpected error in the shader compiler");
}

TEST(DriverLog, AbsurdLineNumbersCountAsUnknown) {
    auto m = parseDriverLog("0:99999999999(3): error: out of range\n");
    ASSERT_EQ(m.size(), 1u);
    expectMessage(m[0], 0, 3, "error", "out of range");
}

TEST(DriverLog, SeverityIsNormalisedToLowerCase) {
    auto m = parseDriverLog("0(7) : fatal error C9999: *** exception during compilation ***\nWarning: deprecated\n");
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 7, 0, "error", "C9999: *** exception during compilation ***");
    expectMessage(m[1], 0, 0, "warning", "deprecated");
}

// ---- Hostile input (issue 11) ----------------------------------------------------

TEST(DriverLog, MesaCandidatesAreOneMessage) {
    // Mesa repeats the location for every candidate of an overloaded call,
    // indented: one message with the first few candidates, not 26 lines.
    std::string log = "0:9(14): error: no matching function for call to `dot(float, vec3)'; candidates are:\n";
    for (const char* c : {"float dot(float, float)", "float dot(vec2, vec2)", "float dot(vec3, vec3)",
                          "float dot(vec4, vec4)", "double dot(double, double)", "double dot(dvec2, dvec2)"})
        log += std::string("0:9(14): error:    ") + c + "\n";
    log += "0:9(14): error: type mismatch\n";
    auto m = parseDriverLog(log);
    ASSERT_EQ(m.size(), 2u);
    expectMessage(m[0], 9, 14, "error",
                  "no matching function for call to `dot(float, vec3)'; candidates are: float dot(float, float); "
                  "float dot(vec2, vec2); float dot(vec3, vec3); float dot(vec4, vec4); and 2 more");
    expectMessage(m[1], 9, 14, "error", "type mismatch");
}

TEST(DriverLog, HugeLinesAreReadWithoutRecursion) {
    // A student's 200,000-character identifier comes back quoted in the log;
    // std::regex recursed once per character on such a line and crashed.
    std::string name(200000, 'a');
    auto m = parseDriverLog("0:3(5): error: `" + name + "' undeclared\n" + std::string(300000, ' ') + "x\n");
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].line, 3);
    EXPECT_LE(m[0].text.size(), 5000u);  // cut: a message quotes, it does not copy
}
