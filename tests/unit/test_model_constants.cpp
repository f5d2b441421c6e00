// The model's constants have one definition in the GLSL (shaders/common.glsl)
// and one in the C++ (the CPU reference: reference/brdf_reference.h,
// core/float_range.h), equal to each other; no other code of the project
// writes the roughness clamp's number. The yardsticks (shaders/yardstick/,
// app/bench/expert*) are the independent copies and keep their own.
#include "core/float_range.h"
#include "core/paths.h"
#include "reference/brdf_reference.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// `const float NAME = VALUE;` in shaders/common.glsl, as a float.
float glslConstant(const std::string& name) {
    const std::string text = rl::test::readText(rl::sourceRoot() / "shaders" / "common.glsl");
    std::smatch m;
    const std::regex definition("const float " + name + " = ([0-9.eE+-]+);");
    if (!std::regex_search(text, m, definition)) return -1.0f;
    return std::stof(m[1]);
}

// The code of a C-like file: comments removed (string literals kept).
std::string codeOf(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "//") == 0) {
            i = text.find('\n', i);
            if (i == std::string::npos) break;
        } else if (text.compare(i, 2, "/*") == 0) {
            i = text.find("*/", i);
            if (i == std::string::npos) break;
            ++i;
            continue;
        }
        out += text[i];
    }
    return out;
}

bool isYardstick(const fs::path& file) {
    const std::string p = file.generic_string();
    return p.find("/shaders/yardstick/") != std::string::npos || p.find("/app/bench/expert") != std::string::npos;
}

// Files under `dir` whose code (comments aside) writes `number`.
std::vector<std::string> filesWriting(const fs::path& dir, const std::string& number) {
    std::vector<std::string> found;
    const std::regex literal("(^|[^0-9.])" + std::regex_replace(number, std::regex("\\."), "\\.") + "([^0-9]|$)");
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || isYardstick(entry.path())) continue;
        if (ext != ".glsl" && ext != ".frag" && ext != ".cpp" && ext != ".h") continue;
        if (std::regex_search(codeOf(rl::test::readText(entry.path())), literal))
            found.push_back(fs::relative(entry.path(), rl::sourceRoot()).generic_string());
    }
    return found;
}

}  // namespace

TEST(ModelConstants, TheGlslAndTheReferenceAgree) {
    EXPECT_EQ(glslConstant("MIN_ROUGHNESS"), float(rl::ref::kMinRoughness));
    EXPECT_EQ(glslConstant("UNIT_ROUNDOFF"), float(rl::kFloatUnitRoundoff));
    EXPECT_EQ(rl::kFloatUnitRoundoff, 0x1p-24);
}

TEST(ModelConstants, TheRoughnessClampIsWrittenOnceInEachLanguage) {
    std::vector<std::string> found;
    for (const char* dir : {"shaders", "course", "exercises", "app"})
        for (const std::string& f : filesWriting(rl::sourceRoot() / dir, "0.045")) found.push_back(f);
    const std::vector<std::string> expected = {"shaders/common.glsl", "app/reference/brdf_reference.h"};
    EXPECT_EQ(std::set<std::string>(found.begin(), found.end()), std::set<std::string>(expected.begin(), expected.end()));
}

TEST(ModelConstants, TheUnitRoundoffIsWrittenOnceInEachLanguage) {
    std::vector<std::string> found;
    for (const char* dir : {"shaders", "app"})
        for (const std::string& f : filesWriting(rl::sourceRoot() / dir, "5.9604644775390625e-8")) found.push_back(f);
    const std::vector<std::string> expected = {"shaders/common.glsl", "app/core/float_range.h"};
    EXPECT_EQ(std::set<std::string>(found.begin(), found.end()), std::set<std::string>(expected.begin(), expected.end()));
}
