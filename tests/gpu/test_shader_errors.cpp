// Compile errors name the file and line the author wrote, followed by that
// source line, on the real driver (Mesa here).
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace rl;

namespace {

// A copy of solutions/ with one file replaced.
fs::path implWith(const std::string& name, const std::string& file, const std::string& text) {
    fs::path dir = test::freshTempDir(name);
    for (const auto& e : fs::directory_iterator(solutionsDir())) fs::copy_file(e.path(), dir / e.path().filename());
    test::writeText(dir / file, text);
    return dir;
}

}  // namespace

TEST(ShaderErrors, CompileErrorNamesStudentFileLineAndSourceLine) {
    std::string broken = test::readText(solutionsDir() / "05-ggx.glsl");
    auto pos = broken.find("    float NoH = dot(n, h);");
    ASSERT_NE(pos, std::string::npos);
    broken.replace(pos, 26, "    float NoH = dot(n, h) +;");
    int line = 1 + int(std::count(broken.begin(), broken.begin() + pos, '\n'));
    fs::path dir = implWith("compile_error", "05-ggx.glsl", broken);
    auto r = test::runRaylab("render -o " + (dir / "x.png").string() + " --size 8x8 --impl " + dir.string());
    EXPECT_EQ(r.status, 1) << r.output;
    std::string where = "05-ggx.glsl:" + std::to_string(line) + ": error: ";
    EXPECT_NE(r.output.find(where), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\n    float NoH = dot(n, h) +;"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(ShaderErrors, UndefinedFunctionInAFrameworkCallNamesTheStudentFile) {
    std::string text = test::readText(solutionsDir() / "07-fresnel.glsl") + "\nfloat broken() { return undefinedThing(); }\n";
    fs::path dir = implWith("undefined", "07-fresnel.glsl", text);
    auto r = test::runRaylab("render -o " + (dir / "x.png").string() + " --size 8x8 --impl " + dir.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("07-fresnel.glsl:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("undefinedThing"), std::string::npos) << r.output;
}

TEST(ShaderErrors, IncludeLeavingTheFolderIsRefused) {
    fs::path dir = implWith("include", "03-lambert.glsl", "#include \"../../../etc/passwd\"\n");
    auto r = test::runRaylab("render -o " + (dir / "x.png").string() + " --size 8x8 --impl " + dir.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("03-lambert.glsl:1: #include \"../../../etc/passwd\": refused"), std::string::npos)
        << r.output;
}

TEST(ShaderErrors, MissingImplementationFileIsNamed) {
    fs::path dir = implWith("missing", "01-camera.glsl", test::readText(solutionsDir() / "01-camera.glsl"));
    fs::remove(dir / "09-reflections.glsl");
    auto r = test::runRaylab("render -o " + (dir / "x.png").string() + " --size 8x8 --impl " + dir.string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("09-reflections.glsl: file not found"), std::string::npos) << r.output;
}
