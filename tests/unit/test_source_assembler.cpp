// #include expansion and the line table that maps driver messages back to
// the files the author wrote.
#include "core/error.h"
#include "shader/program.h"
#include "shader/shader_library.h"
#include "shader/source_assembler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
