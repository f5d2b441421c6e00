// The framework, the ten solutions, every mutant and every alternative
// compile unchanged as GLSL ES 3.00 (WebGL2's language, and the strict rules
// of macOS's and NVIDIA's compilers), so that a portability error can only
// ever be the student's (shader/portability.h). Mesa compiles `#version 300
// es` in the desktop context raylab already has.
#include "course/exercise_registry.h"
#include "core/paths.h"
#include "gl/context.h"
#include "shader/portability.h"
#include "shader/program.h"
#include "shader/shader_library.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace rl;

namespace {

GlContext& context() {
    static auto c = createHeadlessContext(Backend::Auto);
    return *c;
}

std::vector<fs::path> glslFiles(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".glsl") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST(PortableGlsl, TheRayTracerAndEveryProbeBuildAsGlslEs) {
    context();
    Implementation solutions{solutionsDir(), {}};
    AssembledSource vertex = assembleShader("fullscreen.vert", solutions, {}, GlslDialect::Es300);
    // Compiled and linked: the whole program, as a browser builds it.
    EXPECT_NO_THROW(ShaderProgram(vertex, assembleShader("main.frag", solutions, {}, GlslDialect::Es300)));
    for (const ExerciseInfo& e : allExercises()) {
        ShaderDefines only{{"RL_PROBE_EXERCISE", std::to_string(e.number)}};
        EXPECT_NO_THROW(ShaderProgram(vertex, assembleShader("probe.frag", solutions, only, GlslDialect::Es300)))
            << e.id;
    }
}

TEST(PortableGlsl, StrictCompileReallyIsStrict) {
    // The check's premise: the same line builds as desktop GLSL and fails as GLSL ES.
    context();
    fs::path dir = test::freshTempDir("strict");
    for (const auto& f : glslFiles(solutionsDir())) fs::copy_file(f, dir / f.filename());
    std::string text = test::readText(dir / "03-lambert.glsl");
    text.replace(text.find("return albedo / PI;"), 19, "return albedo / PI * 1;");
    test::writeText(dir / "03-lambert.glsl", text);
    Implementation impl{dir, {}};
    AssembledSource vertex = assembleShader("fullscreen.vert", impl, {});
    EXPECT_NO_THROW(ShaderProgram(vertex, assembleShader("main.frag", impl, {})));
    std::string errors = portabilityErrors(assembleShader("main.frag", impl, {}, GlslDialect::Es300));
    EXPECT_NE(errors.find("03-lambert.glsl:"), std::string::npos) << errors;
    EXPECT_NE(errors.find("portability error: an int in float arithmetic: write `return albedo / PI * 1.0;`"), std::string::npos)
        << errors;
}

TEST(PortableGlsl, EveryMutantAndAlternativeIsPortable) {
    // Their verdicts (tests/exercises/test_checker.cpp) stay FAIL and PASS:
    // none of them is turned into a portability error.
    context();
    int checked = 0;
    for (const char* folder : {"mutants", "alternatives"})
        for (const std::string& name : test::unitFileNames(folder)) {
            const fs::path file = test::unitFilePath(folder, name);
            Implementation impl{solutionsDir(), {{name.substr(0, name.find("--")) + ".glsl", file}}};
            EXPECT_EQ(portabilityErrors(assembleShader("main.frag", impl, {}, GlslDialect::Es300)), "") << name;
            ++checked;
        }
    EXPECT_GT(checked, 56);
}
