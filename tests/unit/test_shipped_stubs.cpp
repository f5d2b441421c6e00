// "The unchanged stub" is the stub shipped when the program was built
// (compiled in), never the live exercises/ folder: a student edits that folder
// in place, so comparing with it would call every edited file a stub.
#include "course/exercise_registry.h"
#include "core/paths.h"
#include "render/implementation_facts.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// cmake/shipped_stubs.cmake, run as the build runs it: a student who edited
// exercises/ and rebuilds keeps the real stub; an edited file at the first
// build gives no stub at all (the probes decide), never the student's work.
TEST(ShippedStubs, ARebuildAfterEditingKeepsTheShippedStub) {
    fs::path dir = test::freshTempDir("stub_rebuild");
    fs::create_directories(dir / "exercises");
    // The stubs as shipped (compiled in), never the live exercises/: this
    // test must pass in a clone whose student has edited exercises/ in place.
    for (const ExerciseInfo& e : allExercises()) {
        if (!shippedStub(e.file())) GTEST_SKIP() << "this build has no shipped stub for " << e.file();
        test::writeText(dir / "exercises" / e.file(), stubText(e));
    }
    const ExerciseInfo& ggx = *std::find_if(allExercises().begin(), allExercises().end(),
                                            [](const ExerciseInfo& e) { return e.file() == "05-ggx.glsl"; });
    auto generate = [&](const std::string& snapshot) {
        std::string command = std::string(RAYLAB_CMAKE) + " -DEXERCISES_DIR=" + (dir / "exercises").string() +
                              " -DSNAPSHOT_DIR=" + (dir / snapshot).string() + " -DOUTPUT=" + (dir / "stubs.cpp").string() +
                              " -P " + (sourceRoot() / "cmake" / "shipped_stubs.cmake").string() + " > /dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        return test::readText(dir / "stubs.cpp");
    };
    std::string first = generate("snapshot");
    EXPECT_NE(first.find("\"05-ggx.glsl\""), std::string::npos);
    // The student solves 05 in place and rebuilds: the same stubs as before.
    fs::copy_file(solutionsDir() / "05-ggx.glsl", dir / "exercises" / "05-ggx.glsl", fs::copy_options::overwrite_existing);
    EXPECT_EQ(generate("snapshot"), first);
    EXPECT_EQ(test::readText(dir / "snapshot" / "05-ggx.glsl"), stubText(ggx));
    // A first build after editing: no stub for 05 rather than the solution.
    std::string fresh = generate("fresh-snapshot");
    EXPECT_EQ(fresh.find("\"05-ggx.glsl\""), std::string::npos);
    EXPECT_NE(fresh.find("\"07-fresnel.glsl\""), std::string::npos);
    // An instructor's new stub (still all NOT_STARTED) replaces the old one.
    test::writeText(dir / "exercises" / "07-fresnel.glsl", "// new\nvec3 F_Schlick(vec3 F0, float VoH) {\n    return vec3(NOT_STARTED);\n}\n");
    generate("snapshot");
    EXPECT_EQ(test::readText(dir / "snapshot" / "07-fresnel.glsl"), test::readText(dir / "exercises" / "07-fresnel.glsl"));
}

// A picture program trusts traceRay() only once exercise 09 is written
// (render/define_table.h): the shipped stub keeps the first-hit fallback.
TEST(ShippedStubs, TraceStartedOnlyWhenExercise09IsNoLongerTheStub) {
    EXPECT_TRUE(implementationFacts(Implementation{solutionsDir(), {}}).traceStarted);
    fs::path dir = test::freshTempDir("stub_trace");
    const ExerciseInfo& reflections = findExercise("9");
    test::writeText(dir / reflections.file(), stubText(reflections));
    EXPECT_FALSE(implementationFacts(Implementation{dir, {}}).traceStarted);
    test::writeText(dir / reflections.file(), test::readText(solutionsDir() / reflections.file()));
    EXPECT_TRUE(implementationFacts(Implementation{dir, {}}).traceStarted);
}
