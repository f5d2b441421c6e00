// "The unchanged stub" is the stub shipped when the program was built
// (compiled in), never the live exercises/ folder: a student edits that folder
// in place, so comparing with it would call every edited file a stub.
#include "checks/exercise_registry.h"
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;
using namespace rl;

namespace {

const std::string& stubText(const ExerciseInfo& e) {
    const std::string* stub = shippedStub(e.file());
    if (!stub) throw std::runtime_error("no shipped stub compiled in for " + e.file());
    return *stub;
}

// Every '\n' as CRLF, a UTF-8 byte-order mark, indentation doubled, blank lines added.
std::string reformatted(const std::string& text) {
    std::string out = "\xEF\xBB\xBF\n\t\n";
    for (char c : text) {
        if (c == '\n') out += " \r\n";
        else if (c == ' ') out += "  ";
        else out += c;
    }
    return out + "\n\n\n";
}

// Sets RAYLAB_ROOT for one test, as the wrapper ./raylab does.
struct RootOverride {
    explicit RootOverride(const fs::path& root) { setenv("RAYLAB_ROOT", root.c_str(), 1); }
    ~RootOverride() { unsetenv("RAYLAB_ROOT"); }
};

}  // namespace

TEST(ShippedStubs, EveryExerciseHasOneCompiledIn) {
    for (const ExerciseInfo& e : allExercises()) {
        ASSERT_NE(shippedStub(e.file()), nullptr) << e.file();
        EXPECT_NE(stubText(e).find("NOT_STARTED"), std::string::npos) << e.file();
    }
}

TEST(ShippedStubs, SpacingCrlfAndBomDoNotCount) {
    fs::path dir = test::freshTempDir("stub_spacing");
    for (const ExerciseInfo& e : allExercises()) {
        test::writeText(dir / e.file(), reformatted(stubText(e)));
        EXPECT_TRUE(isUnchangedStub(dir / e.file(), e)) << e.file();
    }
}

TEST(ShippedStubs, OneChangedTokenIsNoStub) {
    fs::path dir = test::freshTempDir("stub_token");
    for (const ExerciseInfo& e : allExercises()) {
        std::string text = stubText(e);
        std::size_t at = text.find("return ");
        ASSERT_NE(at, std::string::npos) << e.file();
        text.insert(at + 7, "-");  // return -NOT_STARTED ...
        test::writeText(dir / e.file(), text);
        EXPECT_FALSE(isUnchangedStub(dir / e.file(), e)) << e.file();
    }
}

TEST(ShippedStubs, NormalFormDropsSpaceAndBomOnly) {
    EXPECT_EQ(normalisedGlsl("\xEF\xBB\xBF" "float f(x) {\r\n\treturn a + c; // d\n}"), "floatf(x){returna+c;//d}");
    EXPECT_NE(normalisedGlsl("a - b"), normalisedGlsl("a + b"));
}

// The bug: a student edits exercises/ in place (the default folder of
// `raylab check`). A scratch root stands for the student's clone: its
// exercises/ holds the solution, and must not be called the stub.
TEST(ShippedStubs, TheLiveExercisesFolderIsNeverConsulted) {
    fs::path root = test::freshTempDir("stub_live");
    fs::create_directories(root / "exercises");
    const fs::path solutions = solutionsDir();
    RootOverride override(root);
    for (const ExerciseInfo& e : allExercises()) {
        fs::path edited = root / "exercises" / e.file();
        fs::copy_file(solutions / e.file(), edited);
        ASSERT_EQ(exercisesDir() / e.file(), edited);
        EXPECT_FALSE(isUnchangedStub(edited, e)) << e.file() << ": an edited file in exercises/ is called the stub";
        // ...and the shipped stub stays the stub even where exercises/ holds something else.
        test::writeText(root / ("stub-" + e.file()), stubText(e));
        EXPECT_TRUE(isUnchangedStub(root / ("stub-" + e.file()), e)) << e.file();
    }
}
