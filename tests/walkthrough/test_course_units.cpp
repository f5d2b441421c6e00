// The course as an instructor adapts it (issue 21), followed word for word in
// a scratch copy of the repository that is then built as the documents say
// (scripts/build.sh; ccache, which every build uses where it is installed,
// makes that a rebuild of what differs):
//
//   Course.AddingAnExercise: docs/instructor.md, "Adding an exercise". Every
//     file that section shows (a "#### `PATH`" heading and the code block
//     under it) is written where it says, the manifest gets its line, and the
//     section's commands run as they are written. The new exercise is NOT
//     STARTED, its solution PASSes, its mutant FAILs with the unit's own
//     hint, the picture with its stub shows the stripes, the default rubric
//     grades it in a column of its own, and the browser page's build takes
//     its unit.
//   Course.ACourseOfNine: "The course manifest": one line (09-reflections)
//     taken out of course/manifest.txt, and the course of nine runs end to end: built, the
//     solutions pass nine of nine, the stubs are nine times NOT STARTED, the
//     grade has nine columns, and the picture is byte for byte the course of
//     ten's (the unit's solution is framework code now).
#include "core/image.h"
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace rl;

namespace {

using test::shellQuoted;

// A copy of the instructor's repository: what git tracks or would add, from
// the working tree, and solutions/ (the build writes it). Under this build's
// folder, so that its own build/ is as deep below it as this build is below
// the source (ccache then finds this build's objects).
fs::path repositoryCopy(const std::string& name) {
    fs::path copy = fs::path(RAYLAB_BUILD_DIR) / "course-walk" / name;
    std::error_code ec;
    fs::remove_all(copy, ec);
    fs::create_directories(copy);
    test::copyRepositoryFiles(copy);
    return copy;
}

// The text of a section of a Markdown page: from its "## " heading to the
// next one outside a fenced block (a handout shown in the section has its own).
std::string section(const std::string& page, const std::string& heading) {
    std::istringstream in(page);
    std::string line, out;
    bool inside = false, fenced = false;
    while (std::getline(in, line)) {
        if (!fenced && line.rfind("## ", 0) == 0) {
            if (inside) break;
            inside = line == heading;
        }
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (inside) out += line + "\n";
    }
    return out;
}

struct DocFile {
    std::string path;
    bool append = false;  // "(one line at the end)"
    std::string text;
};

// Every "#### `PATH`" heading of the section and the fenced block under it.
std::vector<DocFile> filesOf(const std::string& text) {
    std::vector<DocFile> out;
    std::istringstream in(text);
    std::string line;
    const std::regex heading(R"(^#### `([^`]+)`( \(one line at the end\))?$)");
    while (std::getline(in, line)) {
        std::smatch m;
        if (!std::regex_match(line, m, heading)) continue;
        DocFile f{m[1], m[2].matched, ""};
        while (std::getline(in, line) && line.rfind("```", 0) != 0) {}
        while (std::getline(in, line) && line != "```") f.text += line + "\n";
        out.push_back(f);
    }
    return out;
}

// The command lines of the section's ```sh blocks, in order.
std::vector<std::string> commandsOf(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line == "```sh") inside = true;
        else if (line == "```") inside = false;
        else if (inside && !line.empty()) out.push_back(line);
    }
    return out;
}

test::CommandResult runIn(const fs::path& dir, const std::string& command) {
    return test::runShell("cd " + shellQuoted(dir.string()) + " && " + command);
}

// A class of one student whose folder is `impl`'s files: the grade's CSV header.
std::string gradeColumns(const fs::path& repo, const fs::path& impl) {
    fs::path cls = repo / "class";
    fs::create_directories(cls / "alice");
    for (const auto& e : fs::directory_iterator(impl)) fs::copy_file(e.path(), cls / "alice" / e.path().filename());
    test::CommandResult r = runIn(repo, "./raylab grade class -o grades --jobs 2");
    EXPECT_EQ(r.status, 0) << r.output;
    std::ifstream csv(repo / "grades" / "grades.csv");
    std::string header;
    std::getline(csv, header);
    return header;
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(Course, AddingAnExercise) {
    const std::string page = test::readText(sourceRoot() / "docs" / "instructor.md");
    const std::string text = section(page, "## Adding an exercise");
    ASSERT_FALSE(text.empty()) << "docs/instructor.md has no section \"## Adding an exercise\"";
    std::vector<DocFile> files = filesOf(text);
    ASSERT_GE(files.size(), 7u) << "the section shows the unit's files under \"#### `PATH`\" headings";

    fs::path repo = repositoryCopy("adding");
    for (const DocFile& f : files) {
        EXPECT_TRUE(f.path.rfind("course/", 0) == 0) << f.path << ": the section edits a file outside course/";
        EXPECT_TRUE(f.path.rfind("course/13-hemisphere/", 0) == 0 || f.path == "course/manifest.txt") << f.path;
        fs::create_directories((repo / f.path).parent_path());
        std::ofstream out(repo / f.path, f.append ? std::ios::app : std::ios::trunc);
        out << f.text;
    }

    // The section's commands, as written; the first builds the copy.
    std::vector<std::string> commands = commandsOf(text);
    ASSERT_EQ(commands.size(), 6u) << "the commands of the section changed: follow them here too";
    std::vector<test::CommandResult> results;
    for (const std::string& c : commands) results.push_back(runIn(repo, c));
    ASSERT_EQ(commands[0], "scripts/build.sh");
    ASSERT_EQ(results[0].status, 0) << results[0].output;

    EXPECT_EQ(commands[1], "./raylab check --exercise 13");
    EXPECT_EQ(results[1].status, 1) << results[1].output;
    EXPECT_TRUE(std::regex_search(results[1].output, std::regex("13-hemisphere +NOT STARTED"))) << results[1].output;
    EXPECT_NE(results[1].output.find("course/13-hemisphere/stub.glsl"), std::string::npos) << results[1].output;

    EXPECT_EQ(results[2].status, 0) << results[2].output;
    EXPECT_TRUE(std::regex_search(results[2].output, std::regex("13-hemisphere +PASS"))) << results[2].output;

    EXPECT_EQ(results[3].status, 1) << results[3].output;
    EXPECT_TRUE(std::regex_search(results[3].output, std::regex("13-hemisphere +FAIL"))) << results[3].output;
    EXPECT_NE(results[3].output.find("the blend weight is (1 + n.y) / 2, not n.y"), std::string::npos) << results[3].output;

    // The stripes: the frame of the picture with the stub differs from the
    // solutions' picture (a magenta tint in the stripes), its centre less so.
    EXPECT_EQ(results[4].status, 0) << results[4].output;
    EXPECT_EQ(results[5].status, 0) << results[5].output;
    test::CommandResult full = runIn(repo, "./raylab render -o full.png");
    ASSERT_EQ(full.status, 0) << full.output;
    DisplayImage striped = readPng((repo / "stripes.png").string()), whole = readPng((repo / "full.png").string());
    ASSERT_EQ(striped.width, whole.width);
    int magenta = 0, frame = 0;
    for (int y = 0; y < striped.height; ++y)
        for (int x = 0; x < striped.width; ++x) {
            bool edge = x < 6 || y < 6 || x >= striped.width - 6 || y >= striped.height - 6;
            if (!edge) continue;
            ++frame;
            const std::uint8_t* s = striped.at(x, y);
            const std::uint8_t* w = whole.at(x, y);
            int dr = s[0] - w[0], dg = s[1] - w[1], db = s[2] - w[2];
            magenta += dr > 12 && db > 12 && dg < dr;
        }
    EXPECT_GT(magenta, frame / 10) << "no stripes in the frame of the picture with 11's stub";

    // A column of its own in the default rubric.
    std::string header = gradeColumns(repo, repo / "solutions");
    EXPECT_NE(header.find("13-hemisphere"), std::string::npos) << header;
    // The browser page's build takes the unit (scripts/build-web.sh compiles
    // what cmake/course.cmake lists; the page's tabs are the registry's).
    test::CommandResult listed = runIn(repo, "cmake -DRAYLAB_ROOT_DIR=. -DRAYLAB_GENERATED_DIR=web-generated "
                                              "-P cmake/course.cmake && cat web-generated/course_sources.txt");
    EXPECT_EQ(listed.status, 0) << listed.output;
    EXPECT_NE(listed.output.find("course/13-hemisphere/probes.cpp"), std::string::npos) << listed.output;
    // The page's tabs are allExercises() of the units compiled in (web/raylab_web.cpp).
    EXPECT_NE(test::readText(repo / "web-generated" / "course_units.cpp").find("{\"13-hemisphere\", 12,"),
              std::string::npos);
}

TEST(Course, ACourseOfNine) {
    fs::path repo = repositoryCopy("nine");
    const std::string page = test::readText(sourceRoot() / "docs" / "instructor.md");
    ASSERT_NE(section(page, "## The course manifest: removing and reordering").find("**Remove**: delete the line"),
              std::string::npos);
    // The course of ten's picture, before the change.
    test::CommandResult ten = test::runRaylab("render --size 96x72 -o " + (repo / "ten.png").string());
    ASSERT_EQ(ten.status, 0) << ten.output;

    std::string manifest = test::readText(repo / "course" / "manifest.txt");
    // 09: the exercise the framework's specialisations ask about most (traceRay).
    std::size_t at = manifest.find("\n09-reflections\n");
    ASSERT_NE(at, std::string::npos) << manifest;
    manifest.erase(at + 1, std::string("09-reflections\n").size());
    test::writeText(repo / "course" / "manifest.txt", manifest);

    test::CommandResult build = runIn(repo, "scripts/build.sh");
    ASSERT_EQ(build.status, 0) << build.output;
    test::CommandResult solutions = runIn(repo, "./raylab check --impl solutions");
    EXPECT_EQ(solutions.status, 0) << solutions.output;
    EXPECT_NE(solutions.output.find("9 of 9 exercises pass"), std::string::npos) << solutions.output;
    EXPECT_EQ(solutions.output.find("09-reflections"), std::string::npos) << solutions.output;
    test::CommandResult stubs = runIn(repo, "./raylab check");
    EXPECT_EQ(stubs.status, 1) << stubs.output;
    // Nine, and each optional unit's line and summary ("optional 11-environment: NOT STARTED; optional
    // 12-sky-shadows: NOT STARTED").
    EXPECT_EQ(count(stubs.output, "NOT STARTED"), 9 + 2 * 2) << stubs.output;
    EXPECT_NE(stubs.output.find("0 of 9 exercises pass; optional 11-environment: NOT STARTED"), std::string::npos)
        << stubs.output;

    std::string header = gradeColumns(repo, repo / "solutions");
    EXPECT_EQ(header.find("09-reflections"), std::string::npos) << header;
    EXPECT_NE(header.find("08-cook-torrance"), std::string::npos) << header;
    EXPECT_NE(header.find("10-display"), std::string::npos) << header;

    test::CommandResult nine = runIn(repo, "./raylab render --size 96x72 -o nine.png");
    ASSERT_EQ(nine.status, 0) << nine.output;
    EXPECT_EQ(test::readText(repo / "ten.png"), test::readText(repo / "nine.png"))
        << "the picture changed when 09 left the course (its solution is framework code now)";
}

// Units own their exercises (issue 35): 02 and 04 replaced by units of other
// names that provide the same functions (the intersection and the shadow
// test), their folders, manifest lines and students' files renamed, and
// nothing else changed. The course builds and runs end to end: the
// solutions pass ten of ten, the stubs are NOT STARTED under the new names,
// a renamed unit's mutant fails with its hint, the picture is byte for byte
// the original course's, the live view runs (where this build has it), the
// grade has the new columns, and the browser page's build lists the new units.
TEST(Course, TwoUnitsRenamed) {
    fs::path repo = repositoryCopy("renamed");
    test::CommandResult before = test::runRaylab("render --size 96x72 -o " + (repo / "before.png").string());
    ASSERT_EQ(before.status, 0) << before.output;
    const std::vector<std::pair<std::string, std::string>> renames = {{"02-intersect", "02-hit-sphere"},
                                                                      {"04-shadows", "04-occlusion"}};
    std::string manifest = test::readText(repo / "course" / "manifest.txt");
    for (const auto& [from, to] : renames) {
        fs::rename(repo / "course" / from, repo / "course" / to);
        fs::rename(repo / "exercises" / (from + ".glsl"), repo / "exercises" / (to + ".glsl"));
        std::size_t at = manifest.find("\n" + from + "\n");
        ASSERT_NE(at, std::string::npos) << manifest;
        manifest.replace(at + 1, from.size(), to);
    }
    test::writeText(repo / "course" / "manifest.txt", manifest);

    test::CommandResult build = runIn(repo, "scripts/build.sh");
    ASSERT_EQ(build.status, 0) << build.output;
    test::CommandResult solutions = runIn(repo, "./raylab check --impl solutions");
    EXPECT_EQ(solutions.status, 0) << solutions.output;
    EXPECT_NE(solutions.output.find("10 of 10 exercises pass"), std::string::npos) << solutions.output;
    EXPECT_TRUE(std::regex_search(solutions.output, std::regex("02-hit-sphere +PASS"))) << solutions.output;
    EXPECT_TRUE(std::regex_search(solutions.output, std::regex("04-occlusion +PASS"))) << solutions.output;
    test::CommandResult stubs = runIn(repo, "./raylab check -e 2 -e 4");
    EXPECT_EQ(stubs.status, 1) << stubs.output;
    EXPECT_TRUE(std::regex_search(stubs.output, std::regex("02-hit-sphere +NOT STARTED"))) << stubs.output;
    EXPECT_TRUE(std::regex_search(stubs.output, std::regex("04-occlusion +NOT STARTED"))) << stubs.output;
    test::CommandResult mutant =
        runIn(repo, "./raylab check -e 4 --file course/04-occlusion/mutants/fixed-offset.glsl --impl solutions");
    EXPECT_EQ(mutant.status, 1) << mutant.output;
    EXPECT_TRUE(std::regex_search(mutant.output, std::regex("04-occlusion +FAIL"))) << mutant.output;

    test::CommandResult after = runIn(repo, "./raylab render --size 96x72 -o after.png");
    ASSERT_EQ(after.status, 0) << after.output;
    EXPECT_EQ(test::readText(repo / "before.png"), test::readText(repo / "after.png"))
        << "the picture changed when 02 and 04 were renamed";
    test::CommandResult bench = runIn(repo, "./raylab bench --sweeps strategies --size 16x12 --warmup 0 --frames 1 "
                                            "--reference-spp 1");
    EXPECT_EQ(bench.status, 0) << bench.output;
    EXPECT_EQ(bench.output.find("not found"), std::string::npos) << bench.output;
#ifdef RAYLAB_WITH_VIEW_TEST
    test::CommandResult view = runIn(repo, "xvfb-run -a ./raylab view --frames 2 --size 64x48");
    EXPECT_EQ(view.status, 0) << view.output;
#endif

    std::string header = gradeColumns(repo, repo / "solutions");
    EXPECT_NE(header.find("02-hit-sphere"), std::string::npos) << header;
    EXPECT_NE(header.find("04-occlusion"), std::string::npos) << header;
    EXPECT_EQ(header.find("02-intersect"), std::string::npos) << header;
    test::CommandResult listed = runIn(repo, "cmake -DRAYLAB_ROOT_DIR=. -DRAYLAB_GENERATED_DIR=web-generated "
                                              "-P cmake/course.cmake && cat web-generated/course_sources.txt");
    EXPECT_EQ(listed.status, 0) << listed.output;
    EXPECT_NE(listed.output.find("course/04-occlusion/probes.cpp"), std::string::npos) << listed.output;
    EXPECT_NE(test::readText(repo / "web-generated" / "course_units.cpp").find("{\"02-hit-sphere\", 1,"),
              std::string::npos);
}
