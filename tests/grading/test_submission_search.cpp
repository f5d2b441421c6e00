// Finding the student's work the way an instructor would (grading/submission.h),
// without a GPU: the shapes real uploads take, each staged, and the note
// that tells the student which file was graded.
#include "grading/class_fixture.h"
#include "support/test_support.h"

#include "grading/submission.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::test;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Scratch {
    fs::path dir;
    ~Scratch() {
        if (!::testing::Test::HasFailure()) fs::remove_all(dir);
    }
};

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

SubmissionEntry entryFor(const fs::path& path) {
    bool zip = path.extension() == ".zip";
    return {path.stem().string(), path, zip ? SubmissionEntry::Kind::Zip : SubmissionEntry::Kind::Folder, {}};
}

StagedSubmission stage(const fs::path& submission, const fs::path& work) {
    return stageSubmission(entryFor(submission), work / "staged", work / "scratch");
}

// Bytes that deflate cannot shrink (a seeded LCG), like a compiled library.
std::string incompressible(std::size_t size) {
    std::string s(size, '\0');
    std::uint32_t x = 12345;
    for (char& c : s) {
        x = x * 1664525u + 1013904223u;
        c = char(x >> 24);
    }
    return s;
}

}  // namespace

TEST(SubmissionSearch, AStubAtTheTopNeverBeatsACompleteExercisesFolder) {
    Scratch scratch{freshTempDir("search_stub")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    writeFolder(dir / "alice" / "exercises", solutions);
    writeFolder(dir / "alice", stubFiles());  // the template's stubs at the top, shallower and as many
    StagedSubmission s = stage(dir / "alice", dir);
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None);
    EXPECT_EQ(readText(dir / "staged" / "05-ggx.glsl"), solutions["05-ggx.glsl"]) << joined(s.notes);
    EXPECT_TRUE(contains(joined(s.notes), "graded the folder exercises/")) << joined(s.notes);
    EXPECT_TRUE(contains(joined(s.notes), "not graded: 01-camera.glsl")) << joined(s.notes);
}

TEST(SubmissionSearch, ARepositoryZipWithABuildFolderIsGradedNotRefused) {
    Scratch scratch{freshTempDir("search_repo")};
    const fs::path& dir = scratch.dir;
    std::vector<ZipEntry> entries;
    for (const auto& [name, text] : solutionFiles()) entries.push_back({"raylab-main/exercises/" + name, text});
    entries.push_back({"raylab-main/build/libraylab_core.a", incompressible(20u << 20)});  // over the 16 MiB per entry
    entries.push_back({"raylab-main/.git/objects/pack/pack-1.pack", incompressible(1u << 20)});
    entries.push_back({"raylab-main/README.md", "# raylab\n"});
    writeZip(dir / "bob.zip", entries);
    StagedSubmission s = stage(dir / "bob.zip", dir);
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None) << s.problemReason;
    EXPECT_TRUE(fs::exists(dir / "staged" / "10-display.glsl"));
    EXPECT_TRUE(contains(joined(s.notes), "not searched: .git/, build/")) << joined(s.notes);
    EXPECT_FALSE(fs::exists(dir / "scratch")) << "the extracted zip is removed";
}

TEST(SubmissionSearch, DeepFoldersAndZipsInsideZipsAreSearched) {
    Scratch scratch{freshTempDir("search_deep")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    writeFolder(dir / "carol" / "Desktop" / "graphics" / "hw" / "raylab" / "exercises", solutions);
    StagedSubmission deep = stage(dir / "carol", dir / "c");
    EXPECT_EQ(deep.problem, StagedSubmission::Problem::None);
    EXPECT_TRUE(fs::exists(dir / "c" / "staged" / "08-cook-torrance.glsl"));

    std::vector<ZipEntry> inner;
    for (const auto& [name, text] : solutions) inner.push_back({"exercises/" + name, text});
    writeZip(dir / "inner.zip", inner);
    writeZip(dir / "dave.zip", {{"submission/inner.zip", readText(dir / "inner.zip")}, {"notes.txt", "hi"}});
    StagedSubmission nested = stage(dir / "dave.zip", dir / "d");
    EXPECT_EQ(nested.problem, StagedSubmission::Problem::None) << nested.problemReason;
    EXPECT_EQ(readText(dir / "d" / "staged" / "01-camera.glsl"), solutions["01-camera.glsl"]);
    EXPECT_TRUE(contains(joined(nested.notes), "graded the folder submission/inner.zip/exercises/")) << joined(nested.notes);
}

TEST(SubmissionSearch, RenamedCopiesStandInAndTheNoteSaysWhich) {
    Scratch scratch{freshTempDir("search_renamed")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    std::map<std::string, std::string> files = solutions;
    files.erase("05-ggx.glsl");
    files.erase("07-fresnel.glsl");
    files["05-ggx (1).glsl"] = solutions["05-ggx.glsl"];
    files["07-Fresnel.GLSL"] = solutions["07-fresnel.glsl"];
    writeFolder(dir / "erin", files);
    StagedSubmission s = stage(dir / "erin", dir);
    EXPECT_EQ(readText(dir / "staged" / "05-ggx.glsl"), solutions["05-ggx.glsl"]);
    EXPECT_EQ(readText(dir / "staged" / "07-fresnel.glsl"), solutions["07-fresnel.glsl"]);
    EXPECT_TRUE(contains(joined(s.notes), "graded 05-ggx (1).glsl as 05-ggx.glsl")) << joined(s.notes);
    EXPECT_TRUE(contains(joined(s.notes), "graded 07-Fresnel.GLSL as 07-fresnel.glsl")) << joined(s.notes);
}

TEST(SubmissionSearch, AByteOrderMarkIsRemovedAndSaid) {
    Scratch scratch{freshTempDir("search_bom")};
    const fs::path& dir = scratch.dir;
    std::string lambert = solutionFiles()["03-lambert.glsl"];
    writeFolder(dir / "frank", {{"03-lambert.glsl", "\xEF\xBB\xBF" + lambert}});
    StagedSubmission s = stage(dir / "frank", dir);
    EXPECT_EQ(s.refused.count("03-lambert.glsl"), 0u);
    EXPECT_EQ(readText(dir / "staged" / "03-lambert.glsl"), lambert);
    EXPECT_TRUE(contains(joined(s.notes), "byte-order mark at the start of 03-lambert.glsl")) << joined(s.notes);
}

TEST(SubmissionSearch, AFolderNamedLikeAnExerciseIsNoExercise) {
    Scratch scratch{freshTempDir("search_dirname")};
    const fs::path& dir = scratch.dir;
    writeFolder(dir / "gina", {{"01-camera.glsl", solutionFiles()["01-camera.glsl"]},
                               {"06-geometry.glsl/notes.glsl", "// my notes\n"}});
    StagedSubmission s = stage(dir / "gina", dir);
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None);
    EXPECT_FALSE(fs::exists(dir / "staged" / "06-geometry.glsl")) << "nothing the checker could take for a file";
    EXPECT_TRUE(contains(joined(s.notes), "06-geometry.glsl is a folder, not a file")) << joined(s.notes);
}

TEST(SubmissionSearch, ExercisesMissingFromTheGradedFolderAreTakenFromElsewhere) {
    Scratch scratch{freshTempDir("search_spread")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    std::map<std::string, std::string> most = solutions;
    most.erase("09-reflections.glsl");
    writeFolder(dir / "hal" / "exercises", most);
    writeFolder(dir / "hal" / "extra", {{"09-reflections.glsl", solutions["09-reflections.glsl"]}});
    StagedSubmission s = stage(dir / "hal", dir);
    EXPECT_EQ(readText(dir / "staged" / "09-reflections.glsl"), solutions["09-reflections.glsl"]);
    EXPECT_TRUE(contains(joined(s.notes), "09-reflections.glsl: graded extra/09-reflections.glsl")) << joined(s.notes);
}

TEST(SubmissionSearch, WhatWouldNeverFinishOnAGpuIsDecidedBeforeCompiling) {
    Scratch scratch{freshTempDir("search_endless")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    const std::string display = solutions["10-display.glsl"];
    const std::string head = "vec3 toneMap(vec3 c, int op) {\n";
    ASSERT_NE(display.find(head), std::string::npos);
    auto withLoop = [&](const std::string& loop) {
        std::string text = display;
        return text.insert(text.find(head) + head.size(), loop);
    };
    // Endless on a GPU: a constant condition and no way out (llvmpipe alone would stop it and render).
    writeFolder(dir / "a", {{"10-display.glsl", withLoop("    while (true) { c = sin(c); }  // wait\n")},
                            {"07-fresnel.glsl", solutions["07-fresnel.glsl"]}});
    StagedSubmission a = stage(dir / "a", dir / "wa");
    ASSERT_EQ(a.endless.count("10-display.glsl"), 1u) << joined(a.notes);
    const int line = 1 + int(std::count(display.begin(), display.begin() + std::ptrdiff_t(display.find(head)), '\n')) + 1;
    EXPECT_EQ(a.endless["10-display.glsl"].rfind("10-display.glsl:" + std::to_string(line) + ": this loop never ends", 0), 0u)
        << a.endless["10-display.glsl"];
    EXPECT_EQ(a.endless.count("07-fresnel.glsl"), 0u) << "the solutions' loops all end";
    // Loops with a way out, or in a comment, are the checker's business.
    for (const std::string& fine : {std::string("    while (true) { c = sin(c); if (c.x > 0.5) break; }\n"),
                                    std::string("    for (;;) return c;\n"),
                                    std::string("    // while (true) {}\n"),
                                    std::string("    do { c = sin(c); } while (true);\n")}) {
        fs::remove_all(dir / "b");
        fs::remove_all(dir / "wb");
        writeFolder(dir / "b", {{"10-display.glsl", withLoop(fine)}});
        StagedSubmission b = stage(dir / "b", dir / "wb");
        EXPECT_EQ(b.endless.count("10-display.glsl"), 0u) << fine;
    }
    // A macro bomb: refused before the driver's preprocessor spends minutes or gigabytes on it.
    std::string bomb = "#define A0 c\n";
    for (int k = 1; k <= 24; ++k)
        bomb += "#define A" + std::to_string(k) + " A" + std::to_string(k - 1) + " A" + std::to_string(k - 1) + "\n";
    writeFolder(dir / "c", {{"10-display.glsl", withLoop(bomb + "    c = c + A24;\n")}});
    StagedSubmission c = stage(dir / "c", dir / "wc");
    ASSERT_EQ(c.refused.count("10-display.glsl"), 1u);
    EXPECT_TRUE(contains(c.refused["10-display.glsl"], "expands to more than a million tokens (a macro bomb)"))
        << c.refused["10-display.glsl"];
}
