// Portable GLSL (issue 15): `raylab check` compiles the student's file the
// strict way too (GLSL ES 3.00 through Mesa) and reports code that Mesa's
// desktop GLSL accepts but a stricter driver or a browser rejects as a
// COMPILE ERROR marked "portability error", with the student's file and
// line and the fix. One fixture per typical slip in tests/portability/, each
// a solution with one line changed; its header says what the report says.
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace rl;

namespace {

std::vector<std::string> slipFiles() {
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(sourceRoot() / "tests" / "portability"))
        if (e.path().extension() == ".glsl") files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    return files;
}

// The 1-based line of the first line of `text` that contains `what`.
int lineOf(const std::string& text, const std::string& what) {
    auto pos = text.find(what);
    return pos == std::string::npos ? 0 : 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(pos), '\n'));
}

}  // namespace

class PortabilitySlips : public ::testing::TestWithParam<std::string> {};

TEST_P(PortabilitySlips, AreCompileErrorsWithTheFileLineAndFix) {
    fs::path file = sourceRoot() / "tests" / "portability" / GetParam();
    std::string text = test::readText(file);
    std::smatch exercise, slip, report;
    ASSERT_TRUE(std::regex_search(text, exercise, std::regex(R"(// portability slip in: (\d\d)-)")));
    ASSERT_TRUE(std::regex_search(text, slip, std::regex(R"(// slip: (.*)  \(Mesa)")));
    ASSERT_TRUE(std::regex_search(text, report, std::regex(R"re(// reported as: "(.*)")re")));
    // The line the slip is on, below the header that quotes it.
    const std::string body = text.substr(text.find('\n', text.find("// reported as:")) + 1);
    const int line = lineOf(body, slip[1].str()) + lineOf(text, "// reported as:");
    ASSERT_GT(line, 3);
    auto r = test::runRaylab("check --exercise " + exercise[1].str() + " --file " + file.string() + " --output " +
                             test::freshTempDir("slip").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(" COMPILE ERROR "), std::string::npos) << r.output;
    const std::string where = GetParam() + ":" + std::to_string(line) + ": portability error: " + report[1].str();
    EXPECT_NE(r.output.find(where), std::string::npos) << "expected: " << where << "\n" << r.output;
    EXPECT_NE(r.output.find("GLSL ES 3.00"), std::string::npos) << "the hint says why: " << r.output;
}

INSTANTIATE_TEST_SUITE_P(TestsPortability, PortabilitySlips, ::testing::ValuesIn(slipFiles()),
                         [](const auto& info) {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

TEST(PortabilitySlips, SixAreRecorded) { EXPECT_EQ(slipFiles().size(), 6u); }
