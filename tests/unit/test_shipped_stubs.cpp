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

// cmake/course.cmake, run as scripts/build-web.sh runs it, on a copy of the
// units: the shipped stubs are the units' stub.glsl, whatever exercises/
// holds (a student edits that folder in place and rebuilds); the manifest's
// mistakes stop it with the manifest's file and line.
namespace {

struct CourseRun {
    int status;
    std::string output;
};

CourseRun runCourseCmake(const fs::path& root, const fs::path& generated) {
    std::string command = std::string(RAYLAB_CMAKE) + " -DRAYLAB_ROOT_DIR=" + root.string() +
                          " -DRAYLAB_GENERATED_DIR=" + generated.string() + " -P " +
                          (sourceRoot() / "cmake" / "course.cmake").string() + " 2>&1";
    test::CommandResult r = test::runShell(command);
    return {r.status, r.output};
}

}  // namespace

TEST(ShippedStubs, TheUnitsStubsNeverTheExercisesFolder) {
    fs::path root = test::freshTempDir("course_cmake");
    fs::copy(sourceRoot() / "course", root / "course", fs::copy_options::recursive);
    fs::create_directories(root / "exercises");
    // The student solved 05 in place.
    fs::copy_file(root / "course" / "05-ggx" / "solution.glsl", root / "exercises" / "05-ggx.glsl");
    CourseRun run = runCourseCmake(root, root / "generated");
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(test::readText(root / "generated" / "shipped-stubs" / "05-ggx.glsl"),
              test::readText(root / "course" / "05-ggx" / "stub.glsl"));
    const std::string units = test::readText(root / "generated" / "course_units.cpp");
    EXPECT_NE(units.find("{\"05-ggx\", 4,"), std::string::npos);
    EXPECT_NE(units.find(test::readText(root / "course" / "05-ggx" / "stub.glsl")), std::string::npos);
    // solutions/ is written from the units.
    EXPECT_EQ(test::readText(root / "solutions" / "05-ggx.glsl"), test::readText(root / "course" / "05-ggx" / "solution.glsl"));

    // The manifest's mistakes: one line each, naming course/manifest.txt and its line.
    auto manifestError = [&](const std::string& manifest) {
        test::writeText(root / "course" / "manifest.txt", manifest);
        CourseRun r = runCourseCmake(root, root / "generated2");
        EXPECT_NE(r.status, 0) << manifest;
        return r.output;
    };
    EXPECT_NE(manifestError("# the course\n01-camera\n04-shadow\n").find("course/manifest.txt:3: no unit 04-shadow"),
              std::string::npos);
    EXPECT_NE(manifestError("01-camera\nCamera Rays\n").find("course/manifest.txt:2: \"Camera Rays\" is no unit name"),
              std::string::npos);
    EXPECT_NE(manifestError("01-camera\n01-camera\n").find("course/manifest.txt:2: 01-camera is listed twice"),
              std::string::npos);
    EXPECT_NE(manifestError("# nothing\n").find("course/manifest.txt lists no unit"), std::string::npos);
    // A unit left out of the manifest is framework code: it needs its solution.
    fs::remove(root / "course" / "06-geometry" / "solution.glsl");
    std::string out = manifestError("01-camera\n");
    EXPECT_NE(out.find("course/06-geometry is not in course/manifest.txt"), std::string::npos) << out;
    // A unit.json that is no JSON stops the build naming it, with its line.
    fs::copy_file(root / "course" / "05-ggx" / "solution.glsl", root / "course" / "06-geometry" / "solution.glsl");
    test::writeText(root / "course" / "05-ggx" / "unit.json", "{\"title\": \"D\", \"functions\": [\n");
    out = manifestError("05-ggx\n");
    EXPECT_NE(out.find("course/05-ggx/unit.json:2:"), std::string::npos) << out;
    EXPECT_NE(out.find("not one JSON value"), std::string::npos) << out;
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
