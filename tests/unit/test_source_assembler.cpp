// #include expansion and the line table that maps driver messages back to
// the files the author wrote.
#include "core/error.h"
#include "shader/program.h"
#include "shader/shader_library.h"
#include "shader/glsl_scan.h"
#include "shader/source_assembler.h"
#include "shader/source_checks.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rl;

namespace {

class AssemblerTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("raylab_asm_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "lib");
        fs::create_directories(root / "student");
    }
    void TearDown() override { fs::remove_all(root); }
    void write(const fs::path& rel, const std::string& text) { std::ofstream(root / rel) << text; }
    SourceAssembler assembler() {
        return SourceAssembler([](const std::string& name, const fs::path& from) {
            fs::path target = from.parent_path() / name;
            if (!isInside(target, from.parent_path())) throw Error("refused: outside");
            return target;
        });
    }
    fs::path root;
};

}  // namespace

TEST_F(AssemblerTest, IncludesAreExpandedAndEveryLineIsMapped) {
    write("lib/main.frag", "// main\n#include \"a.glsl\"\nvoid main() {}\n");
    write("lib/a.glsl", "float a() {\n  return 1.0;\n}\n");
    AssembledSource s = assembler().assemble("#version 330 core\n", root / "lib/main.frag");
    // prelude (1) + main line 1 + blank for the include + a.glsl (3) + main line 3
    ASSERT_EQ(s.lines.size(), 7u);
    EXPECT_EQ(s.lines[0].file, "<prelude>");
    auto where = s.locate(5);  // "  return 1.0;"
    ASSERT_TRUE(where);
    EXPECT_TRUE(where->file.size() >= 6 && where->file.substr(where->file.size() - 6) == "a.glsl") << where->file;
    EXPECT_EQ(where->line, 2);
    EXPECT_EQ(s.lineText(5), "  return 1.0;");
    auto last = s.locate(7);
    EXPECT_EQ(last->line, 3);
    EXPECT_EQ(s.files.size(), 2u);
}

TEST_F(AssemblerTest, EachFileIsIncludedOnce) {
    write("lib/main.frag", "#include \"a.glsl\"\n#include \"a.glsl\"\n");
    write("lib/a.glsl", "float a();\n");
    AssembledSource s = assembler().assemble("", root / "lib/main.frag");
    EXPECT_EQ(s.text.find("float a();"), s.text.rfind("float a();"));
    EXPECT_NE(s.text.find("float a();"), std::string::npos);
}

TEST_F(AssemblerTest, MissingIncludeNamesTheIncludingLine) {
    write("lib/main.frag", "\n\n#include \"nope.glsl\"\n");
    try {
        assembler().assemble("", root / "lib/main.frag");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("main.frag:3: #include \"nope.glsl\""), std::string::npos) << m;
        EXPECT_NE(m.find("file not found"), std::string::npos) << m;
    }
}

TEST_F(AssemblerTest, IncludeOutsideTheFolderIsRefused) {
    write("student/05-ggx.glsl", "#include \"../lib/a.glsl\"\n");
    write("lib/a.glsl", "float secret();\n");
    try {
        assembler().assemble("", root / "student/05-ggx.glsl");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("05-ggx.glsl:1:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("refused"), std::string::npos) << e.what();
    }
}

TEST_F(AssemblerTest, NonUtf8AndOversizedFilesAreRefused) {
    write("lib/bad.glsl", "float a;\n\xff\xfe broken\n");
    try {
        readSourceFile(root / "lib/bad.glsl");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.glsl:2: file is not UTF-8"), std::string::npos) << e.what();
    }
    write("lib/big.glsl", std::string(kMaxShaderFileBytes + 1, ' '));
    EXPECT_THROW(readSourceFile(root / "lib/big.glsl"), Error);
    EXPECT_THROW(readSourceFile(root / "lib"), Error);
}

// Issue 36: one rule for every command. A Windows-1252 byte in a comment was
// PASS in `grade`, COMPILE ERROR in `check` and refused by `render --ask`:
// every reader of a shader file now reads it as Windows-1252 there, and
// refuses it outside a comment.
TEST_F(AssemblerTest, Windows1252InACommentIsReadAsItIsEverywhere) {
    write("lib/cp.glsl", "// r\xe9sum\xe9\nfloat a; /* \x93quoted\x94 */\n");
    EXPECT_EQ(readSourceFile(root / "lib/cp.glsl"), "// r\xc3\xa9sum\xc3\xa9\nfloat a; /* \xe2\x80\x9cquoted\xe2\x80\x9d */\n");
    write("lib/code.glsl", "// r\xe9sum\xe9\nfloat r\xe9 = 1.0;\n");
    try {
        readSourceFile(root / "lib/code.glsl");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("code.glsl:2: file is not UTF-8 text"), std::string::npos) << e.what();
    }
}

TEST_F(AssemblerTest, VersionLinesAreRejectedWithAHint) {
    write("lib/main.frag", "#version 450\n");
    try {
        assembler().assemble("", root / "lib/main.frag");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("main.frag:1: #version is set by raylab"), std::string::npos);
    }
}

TEST_F(AssemblerTest, DriverLogIsMappedToFileLineAndSourceLine) {
    write("lib/main.frag", "#include \"a.glsl\"\nvoid main() {}\n");
    write("lib/a.glsl", "float a() {\n  return 1.0 +;\n}\n");
    AssembledSource s = assembler().assemble("#version 330 core\n", root / "lib/main.frag");
    // The error is on combined line 4: prelude, blank include line, "float a() {", "  return 1.0 +;".
    auto mesa = mapDriverLog("0:4(15): error: syntax error, unexpected ';'\n", s);
    ASSERT_EQ(mesa.size(), 1u);
    EXPECT_EQ(mesa[0].where.line, 2);
    EXPECT_EQ(mesa[0].sourceLine, "return 1.0 +;");
    std::string formatted = mesa[0].format();
    EXPECT_NE(formatted.find("a.glsl:2: error: syntax error, unexpected ';'\n    return 1.0 +;"), std::string::npos)
        << formatted;
    auto nvidia = mapDriverLog("0(4) : error C0000: syntax error, unexpected ';'\n", s);
    ASSERT_EQ(nvidia.size(), 1u);
    EXPECT_EQ(nvidia[0].where.line, 2);
    auto apple = mapDriverLog("ERROR: 0:4: Syntax error\n", s);
    ASSERT_EQ(apple.size(), 1u);
    EXPECT_EQ(apple[0].where.line, 2);
}

// ---- Hostile and careless input (issue 11) ----------------------------------------

namespace {

// A framework in lib/ (declarations, then two exercise files from student/,
// then framework code using a name) and the exercise files in student/.
class ExerciseFilesTest : public AssemblerTest {
protected:
    void SetUp() override {
        AssemblerTest::SetUp();
        // As the host writes them: the units' signatures in exercise_declarations.glsl.
        write("lib/exercise_declarations.glsl",
              "// 05-ggx\nfloat D_GGX(vec3 n, vec3 h, float alpha);\n"
              "// 07-fresnel\nvec3 F_Schlick(vec3 F0, float VoH);\n");
        write("lib/declarations.glsl",
              "#include \"exercise_declarations.glsl\"\n"
              "// Framework functions the exercises may call:\nfloat helper(float x);\n");
        write("lib/main.frag",
              "#include \"declarations.glsl\"\n#include \"exercise/05-ggx.glsl\"\n#include \"exercise/07-fresnel.glsl\"\n"
              "uniform vec3 u_camera;\nvoid main() {}\n");
        write("student/05-ggx.glsl", ggx);
        write("student/07-fresnel.glsl", fresnel);
    }
    SourceAssembler framework() {
        fs::path lib = root / "lib", student = root / "student";
        return SourceAssembler(
            [student](const std::string& name, const fs::path& from) {
                if (name.rfind("exercise/", 0) == 0) return student / name.substr(9);
                return from.parent_path() / name;
            },
            [lib](const fs::path& file) { return isInside(file, lib); });
    }
    AssembledSource assemble() { return framework().assemble("#version 330 core\n", root / "lib/main.frag"); }
    // The message of the Error that assembling throws, "" when none.
    std::string assembleError() {
        try {
            assemble();
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    }
    // Every host error before compiling, formatted, one per line.
    std::string checked() {
        std::string out;
        for (const ShaderDiagnostic& d : checkExerciseSources(assemble())) out += d.format() + "\n";
        return out;
    }
    std::string ggx = "float D_GGX(vec3 n, vec3 h, float alpha) {\n    return alpha;\n}\n";
    std::string fresnel = "vec3 F_Schlick(vec3 F0, float VoH) {\n    return F0;\n}\n";
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_F(AssemblerTest, LongWhiteSpaceLinesAndHugeIncludeNamesAreHandledLinearly) {
    // A line of 30,000 spaces or tabs crashed std::regex (stack overflow).
    write("lib/main.frag", std::string(30000, ' ') + "\n" + std::string(30000, '\t') + "\nvoid main() {}\n");
    AssembledSource s = assembler().assemble("", root / "lib/main.frag");
    EXPECT_EQ(s.lines.size(), 3u);
    write("lib/main.frag", "\n#include \"" + std::string(200000, 'a') + "\"\n");
    try {
        assembler().assemble("", root / "lib/main.frag");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_TRUE(contains(m, "main.frag:2: #include name is 200000 characters long, over the limit of 255")) << m;
        EXPECT_LT(m.size(), 400u);
    }
}

TEST_F(AssemblerTest, IncludeChainsAreBoundedWithoutRecursion) {
    for (int k = 0; k < 40; ++k)
        write("lib/f" + std::to_string(k) + ".glsl", "#include \"f" + std::to_string(k + 1) + ".glsl\"\n");
    write("lib/f40.glsl", "float a;\n");
    try {
        assembler().assemble("", root / "lib/f0.glsl");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "f15.glsl:1: #include \"f16.glsl\": includes nested more than 16 deep"))
            << e.what();
    }
    write("lib/main.frag", "#include \"a.glsl\n");  // no closing quote
    write("lib/a.glsl", "");
    EXPECT_THROW(assembler().assemble("", root / "lib/main.frag"), Error);
}

TEST_F(AssemblerTest, OnlyRegularFilesAreReadAndTheByteOrderMarkIsDropped) {
    write("lib/bom.glsl", "\xEF\xBB\xBF" "float a;\n");
    EXPECT_EQ(readSourceFile(root / "lib/bom.glsl"), "float a;\n");
    ASSERT_EQ(::mkfifo((root / "lib/fifo.glsl").c_str(), 0600), 0);
    try {
        readSourceFile(root / "lib/fifo.glsl");  // must not wait for a writer
        FAIL();
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "fifo.glsl: is not a regular file")) << e.what();
    }
    EXPECT_THROW(readSourceFile("/dev/zero"), Error);  // never read to the end
    write("lib/main.frag", "#include \"fifo.glsl\"\n");
    try {
        assembler().assemble("", root / "lib/main.frag");
        FAIL();
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "main.frag:1: #include \"fifo.glsl\": ")) << e.what();
        EXPECT_TRUE(contains(e.what(), "fifo.glsl: is not a regular file")) << e.what();
    }
    write("lib/nul.glsl", std::string("float a;\n\0x", 11));
    try {
        readSourceFile(root / "lib/nul.glsl");
        FAIL();
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "nul.glsl:2: file contains a NUL byte")) << e.what();
    }
}

TEST_F(ExerciseFilesTest, EachExerciseFileIsClosedAndRecorded) {
    AssembledSource s = assemble();
    // main.frag, declarations.glsl, exercise_declarations.glsl, then the two exercise files.
    ASSERT_EQ(s.sources.size(), 5u);
    EXPECT_FALSE(s.sources[0].exercise);
    EXPECT_FALSE(s.sources[2].exercise);
    EXPECT_TRUE(s.sources[3].exercise);
    EXPECT_EQ(s.sources[3].includedAs, "exercise/05-ggx.glsl");
    EXPECT_EQ(s.sources[3].owner, 3);
    // After each exercise file, one line that closes its scope, mapped to its last line.
    int markers = 0;
    for (std::size_t k = 0; k < s.lines.size(); ++k) {
        if (!s.lines[k].endOfFile) continue;
        ++markers;
        EXPECT_EQ(s.lines[k].line, 3);
        EXPECT_TRUE(contains(s.lineText(int(k) + 1), "rl_endOfFile")) << s.lineText(int(k) + 1);
    }
    EXPECT_EQ(markers, 2);
    EXPECT_EQ(checked(), "");
}

TEST_F(ExerciseFilesTest, LineDirectivesUnclosedCommentsAndConditionalsAreRefused) {
    write("student/05-ggx.glsl", ggx + "#line 1000\n");
    EXPECT_TRUE(contains(assembleError(), "05-ggx.glsl:4: error: #line is not allowed in exercise files"))
        << assembleError();
    write("student/05-ggx.glsl", ggx + "/* unfinished\nfloat x;\n");
    EXPECT_TRUE(contains(assembleError(), "05-ggx.glsl:4: error: this comment is not closed by the end of the file"))
        << assembleError();
    write("student/05-ggx.glsl", "#ifdef FAST\n" + ggx);
    EXPECT_TRUE(contains(assembleError(), "05-ggx.glsl:1: error: this #if has no #endif")) << assembleError();
    write("student/05-ggx.glsl", ggx + "#endif\n");
    EXPECT_TRUE(contains(assembleError(), "05-ggx.glsl:4: error: #endif without an #if")) << assembleError();
    write("student/05-ggx.glsl", "/* a comment\n#include \"nothing.glsl\"\n*/\n" + ggx);
    EXPECT_EQ(assembleError(), "");  // a directive inside a comment is no directive
}

TEST_F(ExerciseFilesTest, TheContractIsCheckedBeforeCompiling) {
    write("student/05-ggx.glsl", "");
    EXPECT_TRUE(contains(checked(), "05-ggx.glsl: D_GGX is missing (expected float D_GGX(vec3 n, vec3 h, float alpha))\n"))
        << checked();
    write("student/05-ggx.glsl", "float D_GGX(vec3 n, vec3 h, float alpha, float extra) {\n    return alpha;\n}\n");
    EXPECT_TRUE(contains(checked(), "05-ggx.glsl:1: error: D_GGX has the wrong parameters: D_GGX(vec3, vec3, float, "
                                    "float) (expected float D_GGX(vec3 n, vec3 h, float alpha))"))
        << checked();
    write("student/05-ggx.glsl", "vec3 D_GGX(vec3 n, vec3 h, float alpha) {\n    return h;\n}\n");
    EXPECT_TRUE(contains(checked(), "05-ggx.glsl:1: error: D_GGX returns vec3 (expected float D_GGX(")) << checked();
    write("student/05-ggx.glsl", "float D_GGX(vec3 n, vec3 h, float alpha);\n");
    EXPECT_TRUE(contains(checked(), "05-ggx.glsl:1: error: D_GGX is declared but has no body")) << checked();
    // Qualifiers, comments and line breaks are no difference.
    write("student/05-ggx.glsl",
          "highp float D_GGX(const in vec3 n, /* half vector */ in vec3 h,\n                  float alpha)\n{\n"
          "    return alpha;\n}\n");
    EXPECT_EQ(checked(), "");
}

TEST_F(ExerciseFilesTest, NamesDefinedInTwoExerciseFilesAreNamedWithBothPlaces) {
    std::string pow5 = "float pow5(float x) {\n    return x * x * x * x * x;\n}\n";
    write("student/05-ggx.glsl", ggx + pow5);
    write("student/07-fresnel.glsl", pow5 + fresnel);
    std::string out = checked();
    EXPECT_TRUE(contains(out, "07-fresnel.glsl:1: error: pow5(float) is also defined in "));
    EXPECT_TRUE(contains(out, "05-ggx.glsl:4: the exercise files are compiled together, so rename one of them"))
        << out;
    // Overloads are fine; so is the same macro with the same text.
    write("student/07-fresnel.glsl", "float pow5(vec3 x) {\n    return x.x;\n}\n#define EPS 1e-4\n" + fresnel);
    write("student/05-ggx.glsl", ggx + pow5 + "#define EPS 1e-4\n");
    EXPECT_EQ(checked(), "");
    write("student/05-ggx.glsl", ggx + "const float EPS = 1e-4;\n");
    write("student/07-fresnel.glsl", "const float EPS = 1e-3;\n" + fresnel);
    EXPECT_TRUE(contains(checked(), "07-fresnel.glsl:1: error: EPS is also declared in ")) << checked();
    write("student/07-fresnel.glsl", fresnel + "void main() {\n}\n");
    EXPECT_TRUE(contains(checked(), "07-fresnel.glsl:4: error: exercise files must not define main()")) << checked();
}

TEST_F(ExerciseFilesTest, DriverErrorsAtTheEndOfAFileOrInTheFrameworkMoveToTheExerciseFile) {
    auto errorAt = [&](const std::string& file, int line, const std::string& message) {
        AssembledSource s = assemble();
        int combined = 0;
        for (std::size_t k = 0; k < s.lines.size() && !combined; ++k)
            if (contains(s.lines[k].file, file) && (line < 0 ? s.lines[k].endOfFile : s.lines[k].line == line))
                combined = int(k) + 1;
        EXPECT_NE(combined, 0) << file << ":" << line;
        auto d = mapDriverLog("0:" + std::to_string(combined) + "(1): error: " + message + "\n", s);
        return d.empty() ? std::string() : d[0].format();
    };
    // An unclosed brace: the driver stops at the line that closes the scope.
    write("student/05-ggx.glsl", "float D_GGX(vec3 n, vec3 h, float alpha) {\n    if (alpha > 0.0) {\n"
                                 "        return alpha;\n}\n");
    std::string d = errorAt("05-ggx.glsl", -1, "syntax error, unexpected VOID_TOK");
    EXPECT_TRUE(contains(d, "05-ggx.glsl:1: error: this '{' is not closed by the end of the file")) << d;
    // A missing ';' on the last line.
    write("student/05-ggx.glsl", ggx + "const float K = 2.0\n");
    d = errorAt("05-ggx.glsl", -1, "syntax error, unexpected VOID_TOK");
    EXPECT_TRUE(contains(d, "05-ggx.glsl:4: error: the file ends inside a declaration: is a ';' missing")) << d;
    EXPECT_TRUE(contains(d, "\n    const float K = 2.0")) << d;
    // A uniform the framework declares after the exercise: the driver names the framework's line.
    write("student/05-ggx.glsl", "uniform vec3 u_camera;\n" + ggx);
    d = errorAt("main.frag", 4, "`u_camera' redeclared");
    EXPECT_TRUE(contains(d, "05-ggx.glsl:1: error: u_camera is also declared by raylab in ")) << d;
    // Any other error in a framework file says where the cause must be.
    write("student/05-ggx.glsl", ggx);
    d = errorAt("main.frag", 5, "something odd");
    EXPECT_TRUE(contains(d, "main.frag:5: error: something odd [in raylab's own file")) << d;
}

TEST(ShaderErrorFormat, ErrorsAreCappedCountedAndPrintable) {
    std::vector<ShaderDiagnostic> list;
    for (int k = 1; k <= 200; ++k)
        list.push_back({{"exercises/05-ggx.glsl", k}, "error", "`x" + std::to_string(k) + "' undeclared", "x;"});
    list.push_back({{"exercises/05-ggx.glsl", 300}, "error", "\x1b[31m" + std::string(100000, 'y'), ""});
    std::string text = ShaderError("fragment shader", list).what();
    EXPECT_TRUE(contains(text, "05-ggx.glsl:10: error: `x10' undeclared\n    x;\n... and 191 more errors")) << text;
    EXPECT_FALSE(contains(text, "05-ggx.glsl:11:"));
    EXPECT_LT(text.size(), 1000u);
    std::string one = list.back().format();
    EXPECT_TRUE(contains(one, "error: \\x1b[31myyy")) << one.substr(0, 100);
    EXPECT_LT(one.size(), 500u);
}

TEST(GlslScan, TopLevelDeclarationsAndOpenScopes) {
    GlslScan s = scanGlsl(
        "#define EPS  1e-4\nconst float A = 1.0, B[2] = float[2](0.0, EPS);\nuniform vec3 u_x;\n"
        "struct S { float a; };\nfloat f(out vec3 v, float w[3]);\nvec3 g(void) {\n  { return vec3(f(1.0)); }\n}\n");
    ASSERT_EQ(s.functions.size(), 2u);
    EXPECT_EQ(s.functions[0].signature(), "f(out vec3, float[3])");
    EXPECT_FALSE(s.functions[0].hasBody);
    EXPECT_EQ(s.functions[1].declaration(), "vec3 g()");
    EXPECT_TRUE(s.functions[1].hasBody);
    std::string names;
    for (const GlslName& n : s.names) names += n.kind + ":" + n.name + "@" + std::to_string(n.line) + " ";
    EXPECT_EQ(names, "macro:EPS@1 variable:A@2 variable:B@2 variable:u_x@3 struct:S@4 ");
    EXPECT_EQ(s.unclosedBraceLine + s.unclosedParenLine + s.openStatementLine, 0);
    // Deep nesting and long lines cost time, never stack.
    std::string deep = "void f() " + std::string(100000, '{') + "\n" + std::string(30000, ' ') + "(\n";
    GlslScan d = scanGlsl(deep);
    EXPECT_EQ(d.unclosedBraceLine, 1);
    EXPECT_EQ(d.unclosedParenLine, 2);
    EXPECT_EQ(scanGlsl("float x = 1.0\n").openStatementLine, 1);
}
