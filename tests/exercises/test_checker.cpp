// The checker can fail: solutions pass, stubs are NOT STARTED, every mutant
// of the units (course/*/mutants/) is caught by its exercise with a message that names the
// mistake's symptom (and never a cause its header rules out), every correct
// alternative (course/*/alternatives/) passes, compile errors name the
// student's file and line, and a shader that never ends costs its exercise,
// not the run.
#include "core/paths.h"
#include "course/exercise_registry.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace rl;

namespace {

fs::path copyOf(const fs::path& from, const std::string& name) {
    fs::path dir = test::freshTempDir(name);
    for (const auto& e : fs::directory_iterator(from)) fs::copy_file(e.path(), dir / e.path().filename());
    return dir;
}

std::vector<std::string> mutantFiles() { return test::unitFileNames("mutants"); }

int countOf(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
    return n;
}

// A verdict as the check prints it: in an exercise's line (" PASS ") and in
// the summary of the optional ones ("optional 11-environment: PASS; optional
// 12-sky-shadows: PASS (2 s)").
int verdictCount(const std::string& text, const std::string& verdict) {
    return countOf(text, " " + verdict + " ") + countOf(text, " " + verdict + ";");
}

// The manifest's optional exercises (11-environment, 12-sky-shadows): checked, but not in "10 of 10".
int optionalCount() {
    int n = 0;
    for (const ExerciseInfo& e : allExercises()) n += e.optional ? 1 : 0;
    return n;
}

}  // namespace

TEST(Checker, SolutionsPassEveryCheck) {
    auto r = test::runRaylab("check --impl " + solutionsDir().string() + " --output " +
                             test::freshTempDir("sol").string());
    EXPECT_EQ(r.status, 0) << r.output;
    // Each exercise's line, and an optional one's verdict again in the summary.
    EXPECT_EQ(verdictCount(r.output, "PASS"), 10 + 2 * optionalCount()) << r.output;
    EXPECT_NE(r.output.find("10 of 10 exercises pass"), std::string::npos);
}

TEST(Checker, StubsAreNotStartedEverywhere) {
    auto r = test::runRaylab("check --impl " + exercisesDir().string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(verdictCount(r.output, "NOT STARTED"), 10 + 2 * optionalCount()) << r.output;  // and in the summary
}

TEST(Checker, EditedStubsThatStillReturnTheSentinelAreNotStarted) {
    // Not byte-equal to the shipped stub (a comment added), so the check
    // compiles and runs it, and recognises NOT_STARTED in every result.
    fs::path dir = copyOf(exercisesDir(), "edited_stubs");
    std::string text = test::readText(dir / "07-fresnel.glsl") + "\n// I will start tomorrow.\n";
    test::writeText(dir / "07-fresnel.glsl", text);
    auto r = test::runRaylab("check --impl " + dir.string() + " --exercise 7");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("07-fresnel        NOT STARTED   every function still returns NOT_STARTED"),
              std::string::npos)
        << r.output;
}

class Mutants : public ::testing::TestWithParam<std::string> {};

TEST_P(Mutants, AreCaughtWithTheirSymptom) {
    fs::path file = test::unitFilePath("mutants", GetParam());
    std::string text = test::readText(file);
    std::smatch exercise, expect;
    ASSERT_TRUE(std::regex_search(text, exercise, std::regex(R"(// mutant of: (\d\d)-)"))) << "header missing";
    ASSERT_TRUE(std::regex_search(text, expect, std::regex(R"re(// caught by: .* contains "(.*)")re")));
    auto r = test::runRaylab("check --exercise " + exercise[1].str() + " --file " + file.string() + " --output " +
                             test::freshTempDir("mutant").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(" FAIL "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(expect[1].str()), std::string::npos) << "expected the symptom '" << expect[1] << "' in:\n"
                                                                  << r.output;
    // A hint must not name a cause the numbers do not support: the header
    // may list what this mutant must never be told.
    const std::regex never(R"re(// never says: "(.*)")re");
    for (std::sregex_iterator it(text.begin(), text.end(), never), end; it != end; ++it)
        EXPECT_EQ(r.output.find((*it)[1].str()), std::string::npos) << "told '" << (*it)[1] << "' in:\n" << r.output;
}

INSTANTIATE_TEST_SUITE_P(TestsMutants, Mutants, ::testing::ValuesIn(mutantFiles()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// Correct solutions written differently (course/*/alternatives/): the checker
// must not reject a right answer for its form.
std::vector<std::string> alternativeFiles() { return test::unitFileNames("alternatives"); }

class Alternatives : public ::testing::TestWithParam<std::string> {};

TEST_P(Alternatives, Pass) {
    fs::path file = test::unitFilePath("alternatives", GetParam());
    std::smatch exercise;
    std::string text = test::readText(file);
    ASSERT_TRUE(std::regex_search(text, exercise, std::regex(R"(// alternative of: (\d\d)-)"))) << "header missing";
    auto r = test::runRaylab("check --exercise " + exercise[1].str() + " --file " + file.string() + " --output " +
                             test::freshTempDir("alternative").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(" PASS "), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(TestsAlternatives, Alternatives, ::testing::ValuesIn(alternativeFiles()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

TEST(Checker, CompileErrorNamesTheStudentFileAndTheOthersAreStillChecked) {
    fs::path dir = copyOf(solutionsDir(), "compile_error");
    std::string text = test::readText(dir / "05-ggx.glsl");
    auto pos = text.find("    float a2 = alpha * alpha;");
    ASSERT_NE(pos, std::string::npos);
    text.replace(pos, 29, "    float a2 = alpha * alpha");  // missing semicolon
    test::writeText(dir / "05-ggx.glsl", text);
    int line = 1 + int(std::count(text.begin(), text.begin() + pos, '\n'));
    auto r = test::runRaylab("check --impl " + dir.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("05-ggx            COMPILE ERROR"), std::string::npos) << r.output;
    // Mesa reports the error at the next token, on this line or the next.
    bool named = r.output.find("05-ggx.glsl:" + std::to_string(line) + ": error") != std::string::npos ||
                 r.output.find("05-ggx.glsl:" + std::to_string(line + 1) + ": error") != std::string::npos;
    EXPECT_TRUE(named) << r.output;
    EXPECT_EQ(verdictCount(r.output, "PASS"), 9 + 2 * optionalCount()) << r.output;  // the optional's line and summary
}

TEST(Checker, FilesThatPassAloneButClashTogetherFailTheCheck) {
    // Issue 9: `pow5` in 07 and in 09 passes each exercise alone (the others
    // come from solutions/) and breaks `raylab render`, which compiles the ten
    // files together. The check compiles them together too, and says so once.
    fs::path dir = copyOf(solutionsDir(), "together");
    std::string pow5 = "float pow5(float x) {\n    return x * x * x * x * x;\n}\n";
    std::string fresnel = test::readText(dir / "07-fresnel.glsl");
    std::string reflections = test::readText(dir / "09-reflections.glsl");
    test::writeText(dir / "07-fresnel.glsl", fresnel + pow5);
    test::writeText(dir / "09-reflections.glsl", reflections + pow5);
    auto r = test::runRaylab("check --impl " + dir.string() + " --exercise 7 --exercise 9 --output " +
                             test::freshTempDir("together_out").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("07-fresnel        PASS"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("09-reflections    PASS"), std::string::npos) << r.output;
    std::string line07 = std::to_string(countOf(fresnel, "\n") + 1);
    std::string line09 = std::to_string(countOf(reflections, "\n") + 1);
    EXPECT_NE(r.output.find("all files         COMPILE ERROR "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("09-reflections.glsl:" + line09 + ": error: pow5(float) is also defined in "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("07-fresnel.glsl:" + line07 + ": the exercise files are compiled together"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("2 of 2 exercises pass; the files do not compile together"), std::string::npos)
        << r.output;
    // Renamed in one file: nothing more to say.
    test::writeText(dir / "09-reflections.glsl", reflections + "float pow5s(float x) {\n    return x * x * x * x * x;\n}\n");
    r = test::runRaylab("check --impl " + dir.string() + " --exercise 7 --exercise 9 --output " +
                        test::freshTempDir("together_out2").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("all files"), std::string::npos) << r.output;
}

TEST(Checker, ALineOfThirtyThousandSpacesIsJustWhiteSpace) {
    // Issue 11: std::regex in the include expander overflowed the stack on
    // such a line, and `raylab grade` (which runs this checker) scored the
    // otherwise correct exercise 0.
    fs::path file = test::freshTempDir("spaces") / "05-ggx.glsl";
    test::writeText(file, test::readText(solutionsDir() / "05-ggx.glsl") + std::string(30000, ' ') + "\n" +
                              std::string(30000, '\t') + "\n");
    auto r = test::runRaylab("check --exercise 5 --file " + file.string() + " --output " +
                             test::freshTempDir("spaces_out").string());
    EXPECT_EQ(r.status, 0) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find("05-ggx            PASS"), std::string::npos) << r.output.substr(0, 2000);
}

TEST(Checker, AShaderThatNeverEndsCostsItsExerciseOnly) {
    fs::path dir = copyOf(solutionsDir(), "endless");
    std::string text = test::readText(dir / "10-display.glsl");
    auto pos = text.find("vec3 toneMap(vec3 c, int op) {\n");
    ASSERT_NE(pos, std::string::npos);
    // Sixteen endless loops of real work. The loop guard (app/shader/loop_guard.h)
    // ends them after 16384 iterations in all, or the 2 s timeout comes first:
    // TIMEOUT either way, and 07 in the same command is not affected.
    std::string loops = "    vec3 c0 = c;\n";
    for (int k = 0; k < 16; ++k) loops += "    for (int i = 0; i >= 0; ++i) { c = sin(c * 1.0001 + vec3(1e-7)) + cos(c); }\n";
    loops += "    c = c0 + 1e-30 * c;\n";
    text.insert(pos + 31, loops);
    test::writeText(dir / "10-display.glsl", text);
    auto r = test::runRaylab("check --impl " + dir.string() + " --exercise 10 --exercise 7 --timeout 2");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("10-display        TIMEOUT"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("07-fresnel        PASS"), std::string::npos) << r.output;
}

TEST(Checker, BadCommandLine) {
    auto e = test::runRaylab("check --exercise 13");  // 11 and 12 are the optional 11-environment and 12-sky-shadows
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.output.find("--exercise: no exercise '13'"), std::string::npos) << e.output;
    auto d = test::runRaylab("check --impl /nonexistent");
    EXPECT_EQ(d.status, 1);
    EXPECT_EQ(d.output, "raylab: error: --impl: /nonexistent is not a directory\n");
}

TEST(Checker, AnyMixOfStubsAndSolutionsRenders) {
    // Stubs for the odd exercises, solutions for the even ones, and the other way round.
    for (int parity = 0; parity < 2; ++parity) {
        fs::path dir = copyOf(solutionsDir(), "mix" + std::to_string(parity));
        int k = 0;
        for (const auto& e : fs::directory_iterator(exercisesDir()))
            if (++k % 2 == parity) fs::copy_file(e.path(), dir / e.path().filename(), fs::copy_options::overwrite_existing);
        auto r = test::runRaylab("render --size 32x24 --impl " + dir.string() + " -o " + (dir / "x.png").string() +
                                 " --hdr " + (dir / "x.pfm").string());
        EXPECT_EQ(r.status, 0) << r.output;
    }
    auto stubs = test::runRaylab("render --size 32x24 --impl " + exercisesDir().string() + " -o /tmp/raylab_stubs.png");
    EXPECT_EQ(stubs.status, 0) << stubs.output;
}
