// Issue 22: every name an LMS download can hold becomes exactly one student
// (or one listed reason), without a GPU: Canvas names with Unicode letters,
// anonymous grading, late and resubmission markers, names that are not
// UTF-8; a submission of 10,000 files; CSV cells that a spreadsheet would run;
// Windows-1252 bytes in comments.
#include "grading/class_fixture.h"
#include "support/test_support.h"

#include "grading/entry_name.h"
#include "grading/grades_csv.h"
#include "core/legacy_text.h"
#include "grading/roster.h"
#include "grading/similarity.h"
#include "grading/submission.h"

#include <gtest/gtest.h>

#include <map>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::test;

namespace {

struct Scratch {
    fs::path dir;
    ~Scratch() {
        if (!::testing::Test::HasFailure()) fs::remove_all(dir);
    }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

}  // namespace

// Canvas's content_zipper.rb: sanitize_file_name keeps [[:word:]] (Unicode
// letters), "_LATE" after the name, "anon_<id>" with anonymous grading.
TEST(LmsNames, CanvasNamesWithUnicodeLettersAnonymousAndLateAreTakenApart) {
    LmsDownloadName u = parseLmsDownloadName("m\xC3\xBCllerj\xC3\xBCrgen_1005_70021_01-camera.glsl");
    EXPECT_EQ(u.kind, LmsDownloadName::Kind::Canvas);
    EXPECT_EQ(u.student, "m\xC3\xBCllerj\xC3\xBCrgen_1005");
    EXPECT_EQ(u.file, "01-camera.glsl");
    LmsDownloadName zh = parseLmsDownloadName("\xE6\x9D\x8E\xE9\x9B\xB7_1006_70022_05-ggx-1.glsl");  // 李雷
    EXPECT_EQ(zh.kind, LmsDownloadName::Kind::Canvas);
    EXPECT_EQ(zh.number, "1006");
    EXPECT_EQ(zh.file, "05-ggx-1.glsl");
    LmsDownloadName late = parseLmsDownloadName("garc\xC3\xAD" "amar\xC3\xAD" "a_LATE_1007_70023_01-camera.glsl");
    EXPECT_TRUE(late.late);
    EXPECT_EQ(late.student, "garc\xC3\xAD" "amar\xC3\xAD" "a_1007");
    LmsDownloadName anon = parseLmsDownloadName("anon_x7Kq2_70024_01-camera.glsl");
    EXPECT_EQ(anon.kind, LmsDownloadName::Kind::Canvas);
    EXPECT_TRUE(anon.anonymous);
    EXPECT_EQ(anon.student, "anon_x7Kq2");
    EXPECT_EQ(anon.file, "01-camera.glsl");
    LmsDownloadName anonLate = parseLmsDownloadName("LATE_anon_x7Kq2_70025_exercises.zip");
    EXPECT_TRUE(anonLate.anonymous && anonLate.late);
    EXPECT_EQ(anonLate.student, "anon_x7Kq2");
    // Not Canvas: punctuation Canvas removes, upper case it lowers, too few ids.
    EXPECT_EQ(parseLmsDownloadName("Doe, Jane_1_2_x.glsl").kind, LmsDownloadName::Kind::None);
    EXPECT_EQ(parseLmsDownloadName("Lab_1_2_final.zip").kind, LmsDownloadName::Kind::None);
    EXPECT_EQ(parseLmsDownloadName("exercises_2").kind, LmsDownloadName::Kind::None);
    // Moodle folders keep the full name as it is (blind marking: "Participant_<id>").
    EXPECT_EQ(parseLmsDownloadName("J\xC3\xBCrgen M\xC3\xBCller_4301_assignsubmission_file_").student,
              "J\xC3\xBCrgen M\xC3\xBCller_4301");
    EXPECT_EQ(parseLmsDownloadName("Participant_4302_assignsubmission_file_").student, "Participant_4302");
}

TEST(LmsNames, EscapedIdsAreStableUniqueAndPlainUtf8) {
    EXPECT_TRUE(isPlainUtf8("m\xC3\xBCllerj\xC3\xBCrgen_1005"));
    EXPECT_FALSE(isPlainUtf8("caf\xE9"));
    EXPECT_FALSE(isPlainUtf8("x\x1B[31mred"));
    EXPECT_FALSE(isPlainUtf8("\xC0\xAF"));  // an overlong '/'
    EXPECT_EQ(safeEntryId("caf\xE9"), "caf%E9");
    EXPECT_EQ(safeEntryId("100%\xFF"), "100%25%FF");
    EXPECT_EQ(safeEntryId("x\x1B[31m"), "x%1B[31m");
    EXPECT_EQ(safeEntryId("m\xC3\xBCller"), "m\xC3\xBCller");
    EXPECT_EQ(hexBytes("a\xFF"), "61 ff");
}

// Before: the Unicode and anonymous Canvas files were "ignored (not a folder
// or .zip)", and a name with byte 0xFF stopped the run at summary.json.
TEST(LmsNames, EveryStudentOfAMixedDownloadIsListedOnceUnderASafeId) {
    Scratch scratch{freshTempDir("lms_names")};
    const fs::path& dir = scratch.dir;
    const std::string camera = solutionFiles()["01-camera.glsl"];
    writeText(dir / "m\xC3\xBCllerj\xC3\xBCrgen_1005_70021_01-camera.glsl", camera);
    writeText(dir / "\xE6\x9D\x8E\xE9\x9B\xB7_1006_70022_01-camera-1.glsl", camera);
    writeText(dir / "garc\xC3\xAD" "amar\xC3\xAD" "a_LATE_1007_70023_01-camera.glsl", camera);
    writeText(dir / "anon_x7Kq2_70024_01-camera.glsl", camera);
    writeText(dir / "LATE_anon_p9Zt4_70026_01-camera.glsl", camera);
    writeFolder(dir / "caf\xE9", {{"01-camera.glsl", camera}});
    writeZip(dir / "bad\xFFname.zip", {{"01-camera.glsl", camera}});
    writeText(dir / "notes\x1B[2J.txt", "x");
    SubmissionList list = listSubmissions(dir);
    std::vector<std::string> ids;
    for (const SubmissionEntry& e : list.students) ids.push_back(e.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"anon_p9Zt4", "anon_x7Kq2", "bad%FFname", "caf%E9",
                                             "garc\xC3\xAD" "amar\xC3\xAD" "a_1007", "m\xC3\xBCllerj\xC3\xBCrgen_1005",
                                             "\xE6\x9D\x8E\xE9\x9B\xB7_1006"}));
    for (const std::string& id : ids) EXPECT_TRUE(isPlainUtf8(id)) << id;
    ASSERT_EQ(list.ignored.size(), 1u);
    EXPECT_EQ(list.ignored[0].rfind("notes%1B[2J.txt (", 0), 0u) << list.ignored[0];
    for (const SubmissionEntry& e : list.students) {
        Scratch work{freshTempDir("lms_names_stage")};
        StagedSubmission s = stageSubmission(e, work.dir / "staged", work.dir / "scratch");
        EXPECT_EQ(s.problem, StagedSubmission::Problem::None) << e.id << ": " << s.problemReason;
        EXPECT_EQ(readText(work.dir / "staged" / "01-camera.glsl"), camera) << e.id << "\n" << joined(s.notes);
    }
}

// Before: the walk stopped after 5,000 entries in directory order, and the
// finished exercise beside them was graded NOT STARTED.
TEST(LmsNames, AnExerciseBesideTenThousandFilesIsFound) {
    Scratch scratch{freshTempDir("many_files")};
    const fs::path& dir = scratch.dir;
    const std::string ggx = solutionFiles()["05-ggx.glsl"];
    fs::create_directories(dir / "me" / "generated");
    for (int k = 0; k < 10000; ++k) writeText(dir / "me" / "generated" / ("f" + std::to_string(k) + ".txt"), "x");
    writeFolder(dir / "me" / "zz-last", {{"05-ggx.glsl", ggx}});
    StagedSubmission s = stageSubmission({"me", dir / "me", SubmissionEntry::Kind::Folder, {}}, dir / "staged",
                                         dir / "scratch");
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None) << s.problemReason;
    ASSERT_TRUE(fs::exists(dir / "staged" / "05-ggx.glsl")) << joined(s.notes);
    EXPECT_EQ(readText(dir / "staged" / "05-ggx.glsl"), ggx);
    EXPECT_TRUE(contains(joined(s.notes), "more than 5000 files; among the rest only files named as exercises"))
        << joined(s.notes);
    // Issue 36: the note counted the 4,987 files looked at, not the 10,000 there were.
    EXPECT_TRUE(contains(joined(s.notes), "ignored 10000 files that are not part of the exercises")) << joined(s.notes);
}

// OWASP: a cell starting with = + - @ tab or CR gets a leading '; numbers stay numbers.
TEST(LmsNames, CsvCellsNeverStartAFormula) {
    EXPECT_EQ(csvField("=HYPERLINK(\"http://x\")"), "\"'=HYPERLINK(\"\"http://x\"\")\"");
    EXPECT_EQ(csvField("+49 30 1234"), "'+49 30 1234");
    EXPECT_EQ(csvField("-cmd"), "'-cmd");
    EXPECT_EQ(csvField("@SUM(A1)"), "'@SUM(A1)");
    EXPECT_EQ(csvField("\tx"), "'\tx");
    EXPECT_EQ(csvField("\rx"), "\"'\rx\"");
    EXPECT_EQ(csvField("-1.50"), "-1.50");
    EXPECT_EQ(csvField("+2"), "+2");
    EXPECT_EQ(csvField("100.00"), "100.00");
    EXPECT_EQ(csvField("doejane_1001"), "doejane_1001");
}

// Before: "file is not UTF-8 text" and 0 points for an "é" in a comment.
TEST(LmsNames, Windows1252InCommentsIsReadWithANoteAndElsewhereNamed) {
    LegacyTextResult r = commentsFromWindows1252("// caf\xE9 \x93quoted\x94\nfloat x; /* \x80 */\n");
    EXPECT_EQ(r.text, "// caf\xC3\xA9 \xE2\x80\x9Cquoted\xE2\x80\x9D\nfloat x; /* \xE2\x82\xAC */\n");
    EXPECT_EQ(r.converted, 4u);
    EXPECT_EQ(r.firstConvertedLine, 1);
    EXPECT_EQ(r.badLine, 0);
    LegacyTextResult bad = commentsFromWindows1252("// ok \xE9\nfloat caf\xE9 = 1.0;\n");
    EXPECT_EQ(bad.badLine, 2);
    EXPECT_EQ(bad.badByte, 0xE9);
    EXPECT_EQ(bad.badOffset, 17u);
    EXPECT_EQ(commentsFromWindows1252("// m\xC3\xBCller\n").converted, 0u) << "UTF-8 stays as it is";

    Scratch scratch{freshTempDir("cp1252")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> files = solutionFiles();
    writeFolder(dir / "me", {{"03-lambert.glsl", "// r\xE9sum\xE9 of Lambert\n" + files["03-lambert.glsl"]},
                             {"05-ggx.glsl", files["05-ggx.glsl"] + "\nfloat na\xEFve = 1.0;\n"}});
    StagedSubmission s = stageSubmission({"me", dir / "me", SubmissionEntry::Kind::Folder, {}}, dir / "staged",
                                         dir / "scratch");
    EXPECT_EQ(s.refused.count("03-lambert.glsl"), 0u) << s.refused["03-lambert.glsl"];
    EXPECT_TRUE(contains(readText(dir / "staged" / "03-lambert.glsl"), "// r\xC3\xA9sum\xC3\xA9 of Lambert"));
    EXPECT_TRUE(contains(joined(s.notes), "03-lambert.glsl: 2 bytes in comments (first on line 1) are not UTF-8 and "
                                          "were read as Windows-1252"))
        << joined(s.notes);
    ASSERT_EQ(s.refused.count("05-ggx.glsl"), 1u);
    EXPECT_TRUE(contains(s.refused["05-ggx.glsl"], "05-ggx.glsl:"));
    EXPECT_TRUE(contains(s.refused["05-ggx.glsl"], ": file is not UTF-8 text: byte 0xEF")) << s.refused["05-ggx.glsl"];
}

// Copies, the way MOSS and Dolos find them (issue 36): identical files are
// one cluster however many students share them; a renamed copy, a reordered
// copy and one with other white space and comments are found; the stub, the
// solution and short files many students share are base code, never evidence.
TEST(Similarity, ClustersSeeThroughRenamingAndReorderingAndDropBaseCode) {
    const std::string own = ownCookTorrance(0);
    std::string spaced = "// my own work\n" + own;
    for (std::size_t at = 0; (at = spaced.find("    ", at)) != std::string::npos;) spaced.replace(at, 4, "\t");
    const std::string solution = solutionFiles()["08-cook-torrance.glsl"], stub = stubFiles()["08-cook-torrance.glsl"];
    std::vector<SimilarityFile> files = {
        {"ann", "08-cook-torrance", own},
        {"bob", "08-cook-torrance", renamedCopy(own, "zz")},
        {"cy", "08-cook-torrance", reorderedCopy(own)},
        {"dee", "08-cook-torrance", spaced},
        {"eve", "08-cook-torrance", ownCookTorrance(1)},  // written by someone else
        {"fay", "08-cook-torrance", ownCookTorrance(2)},
    };
    // Twelve students with the solution, twelve with the stub, and ten with one identical short file.
    for (int k = 0; k < 12; ++k) files.push_back({"sol" + std::to_string(k), "08-cook-torrance", solution});
    for (int k = 0; k < 12; ++k) files.push_back({"stub" + std::to_string(k), "08-cook-torrance", stub});
    const std::string shortOne = "vec3 F_Schlick(vec3 F0, float VoH) {\n    return F0 + (1.0 - F0) * pow(1.0 - VoH, 5.0);\n}\n";
    for (int k = 0; k < 10; ++k) files.push_back({"short" + std::to_string(k), "07-fresnel", shortOne});
    // Ten students handing in one long file of their own (not the solution): one cluster, not 45 pairs.
    for (int k = 0; k < 10; ++k) files.push_back({"ten" + std::to_string(k), "09-reflections", "// shared\n" + ownCookTorrance(7)});
    for (int k = 0; k < 60; ++k) files.push_back({"other" + std::to_string(k), "09-reflections", solutionFiles()["09-reflections.glsl"]});
    const std::vector<SimilarityFile> base = {{"", "08-cook-torrance", stub}, {"", "08-cook-torrance", solution},
                                              {"", "07-fresnel", stubFiles()["07-fresnel.glsl"]},
                                              {"", "07-fresnel", solutionFiles()["07-fresnel.glsl"]}};
    SimilarityReport report = findSimilarSubmissions(files, base);
    std::vector<std::string> found;
    for (const SimilarCluster& c : report.clusters) {
        std::string who;
        for (const std::string& s : c.students) who += (who.empty() ? "" : " ") + s;
        found.push_back(who + (c.identical ? " identical" : " similar"));
    }
    ASSERT_EQ(found.size(), 2u) << ::testing::PrintToString(found);
    EXPECT_EQ(found[0], "ten0 ten1 ten2 ten3 ten4 ten5 ten6 ten7 ten8 ten9 identical");
    EXPECT_EQ(found[1], "ann bob cy dee similar");
    EXPECT_EQ(report.clusters[1].studentCount, 4u);
    EXPECT_GE(report.clusters[1].similarity, 0.9);
    EXPECT_GE(report.clusters[1].lines.size(), 3u) << "shared lines, side by side";
    // The copies as pairs (ann and dee are one file after comments and white space).
    std::map<std::string, double> pairs;
    for (const SimilarPair& p : report.clusters[1].pairs) pairs[p.a + "-" + p.b] = p.similarity;
    ASSERT_TRUE(pairs.count("ann-bob") && pairs.count("ann-cy")) << ::testing::PrintToString(pairs);
    EXPECT_GE(pairs["ann-bob"], 0.95) << "renamed";
    EXPECT_GE(pairs["ann-cy"], 0.95) << "reordered";
    EXPECT_EQ(withoutCommentsOrSpacing("float  x = 1.0; // one\n/* two */ float y;\n"), "float x = 1.0 ; float y ;");
    EXPECT_EQ(normalisedTokens("float myName = dot(a.xyz, b);"), "float $ = dot ( $ . xyz , $ ) ;");

    // Bounded: a class of 2,000 where every pair of neighbours copied: at most `limit` entries.
    std::vector<SimilarityFile> many;
    for (int k = 0; k < 2000; ++k) {
        std::string text = "float own(float x) {\n";
        for (int j = 0; j < 8; ++j)
            text += "    x = x * " + std::to_string(k / 2 * 8 + j) + ".5 + " + std::to_string(j) + ".25 / (x + 1.0);\n";
        many.push_back({"s" + std::to_string(10000 + k), "08-cook-torrance", text + "    return x;\n}\n"});
    }
    SimilarityReport big = findSimilarSubmissions(many, base, 50);
    EXPECT_EQ(big.clusters.size(), 50u);
    EXPECT_EQ(big.clustersFound, 1000u);
}
