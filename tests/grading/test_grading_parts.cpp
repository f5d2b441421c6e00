// The grader's parts without a GPU or a child process: safe unzip, staging
// of submissions, rubric arithmetic, CSV, shards, merge refusals.
#include "grading/class_fixture.h"
#include "grading/atomic_file.h"
#include "support/test_support.h"

#include "core/error.h"
#include "grading/grade_run.h"
#include "grading/grades_csv.h"
#include "grading/gradescope_results.h"
#include "grading/merge.h"
#include "grading/rubric.h"
#include "grading/safe_unzip.h"
#include "grading/student_grade.h"
#include "grading/submission.h"
#include "grading/summary.h"
#include "grading/outputs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <sstream>
#include <sys/stat.h>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::test;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string refusalOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A test's folder, removed when the test passes (kept to look at when it fails).
struct Scratch {
    fs::path dir;
    ~Scratch() {
        if (!::testing::Test::HasFailure()) fs::remove_all(dir);
    }
};

SubmissionEntry folderEntry(const fs::path& path) { return {path.filename().string(), path, SubmissionEntry::Kind::Folder}; }

}  // namespace

// ---- safe unzip -------------------------------------------------------------------------

TEST(SafeUnzip, ExtractsNestedFiles) {
    Scratch scratch{freshTempDir("unzip_ok")};
    const fs::path& dir = scratch.dir;
    writeZip(dir / "a.zip", {{"exercises/", ""}, {"exercises/01-camera.glsl", "// one\n"}, {"notes.txt", "x"}});
    UnzipResult r = extractZipSafely(dir / "a.zip", dir / "out");
    EXPECT_EQ(r.files, 2u);
    EXPECT_EQ(readText(dir / "out" / "exercises" / "01-camera.glsl"), "// one\n");
}

TEST(SafeUnzip, RefusesEntriesThatLeaveTheFolder) {
    Scratch scratch{freshTempDir("unzip_slip")};
    const fs::path& dir = scratch.dir;
    for (const std::string& name : {"../evil.glsl", "a/../../evil.glsl", "/tmp/evil.glsl", "C:/evil.glsl", "a\\..\\evil"}) {
        writeZip(dir / "slip.zip", {{"ok.glsl", "ok"}, {name, "evil"}});
        std::string why = refusalOf([&] { extractZipSafely(dir / "slip.zip", dir / "out"); });
        EXPECT_TRUE(contains(why, "slip.zip: refused")) << name << ": " << why;
        EXPECT_FALSE(fs::exists(dir / "out")) << name << ": nothing is extracted from a refused zip";
        EXPECT_FALSE(fs::exists(dir / "evil.glsl"));
    }
}

TEST(SafeUnzip, LeavesSymlinkEntriesOutAndSaysSo) {
    Scratch scratch{freshTempDir("unzip_link")};
    const fs::path& dir = scratch.dir;
    writeZip(dir / "l.zip", {{"05-ggx.glsl", "/etc/passwd", true}, {"01-camera.glsl", "// one\n"}});
    UnzipResult r = extractZipSafely(dir / "l.zip", dir / "out");
    EXPECT_EQ(r.files, 1u);
    ASSERT_EQ(r.refused.count("05-ggx.glsl"), 1u);
    EXPECT_TRUE(contains(r.refused["05-ggx.glsl"], "symbolic link"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "out" / "05-ggx.glsl")));
}

TEST(SafeUnzip, RefusesZipBombsByRatioTotalAndCount) {
    Scratch scratch{freshTempDir("unzip_bomb")};
    const fs::path& dir = scratch.dir;
    writeZip(dir / "ratio.zip", {{"zeros.glsl", std::string(4u << 20, '\0')}});
    EXPECT_TRUE(contains(refusalOf([&] { extractZipSafely(dir / "ratio.zip", dir / "o1"); }), "compression ratio"));
    UnzipLimits small;
    small.maxTotalBytes = 1000;
    writeZip(dir / "total.zip", {{"a.glsl", std::string(600, 'a')}, {"b.glsl", std::string(600, 'b')}});
    EXPECT_TRUE(contains(refusalOf([&] { extractZipSafely(dir / "total.zip", dir / "o2", small); }), "limit"));
    EXPECT_FALSE(fs::exists(dir / "o2"));
    UnzipLimits few;
    few.maxEntries = 2;
    writeZip(dir / "many.zip", {{"a", "a"}, {"b", "b"}, {"c", "c"}});
    EXPECT_TRUE(contains(refusalOf([&] { extractZipSafely(dir / "many.zip", dir / "o3", few); }), "3 entries"));
}

TEST(SafeUnzip, RefusesCorruptArchives) {
    Scratch scratch{freshTempDir("unzip_corrupt")};
    const fs::path& dir = scratch.dir;
    writeText(dir / "bad.zip", "PK\x03\x04 and then nothing");
    EXPECT_TRUE(contains(refusalOf([&] { extractZipSafely(dir / "bad.zip", dir / "o"); }), "bad.zip: not a valid zip"));
    // A real archive cut in half.
    writeZip(dir / "whole.zip", {{"a.glsl", std::string(50000, 'a') + "xyz"}});
    std::string bytes = readText(dir / "whole.zip");
    writeText(dir / "half.zip", bytes.substr(0, bytes.size() / 2));
    EXPECT_FALSE(refusalOf([&] { extractZipSafely(dir / "half.zip", dir / "o2"); }).empty());
}

// ---- submissions ------------------------------------------------------------------------

TEST(Submissions, IdsFromFoldersAndZipsSortedAndUnique) {
    Scratch scratch{freshTempDir("list")};
    const fs::path& dir = scratch.dir;
    fs::create_directories(dir / "bob");
    fs::create_directories(dir / "alice");
    writeText(dir / "alice.zip", "");
    writeText(dir / "Carol.ZIP", "");
    writeText(dir / "roster.csv", "");
    fs::create_directories(dir / ".git");
    fs::create_symlink("bob", dir / "mallory");
    SubmissionList list = listSubmissions(dir);
    std::vector<std::string> ids;
    for (const SubmissionEntry& e : list.students) ids.push_back(e.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"Carol", "alice", "alice.zip", "bob", "mallory"}));
    EXPECT_EQ(list.students[4].kind, SubmissionEntry::Kind::Link);
    EXPECT_EQ(list.ignored.size(), 2u);
    EXPECT_TRUE(contains(refusalOf([&] { listSubmissions(dir / "none"); }), "none: not a folder of submissions"));
}

TEST(Submissions, SymlinkedFilesAndFifosAreRefusedNeverRead) {
    Scratch scratch{freshTempDir("stage_link")};
    const fs::path& dir = scratch.dir;
    writeFolder(dir / "other", {{"05-ggx.glsl", "// someone else's\n"}});
    writeFolder(dir / "me", {{"01-camera.glsl", "// mine\n"}});
    fs::create_symlink("../other/05-ggx.glsl", dir / "me" / "05-ggx.glsl");
    fs::create_symlink("/etc/passwd", dir / "me" / "helper.glsl");
    ASSERT_EQ(mkfifo((dir / "me" / "06-geometry.glsl").c_str(), 0644), 0);  // would block a reader forever
    StagedSubmission s = stageSubmission(folderEntry(dir / "me"), dir / "staged", dir / "scratch");
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None);
    ASSERT_EQ(s.refused.count("05-ggx.glsl"), 1u);
    EXPECT_TRUE(contains(s.refused["05-ggx.glsl"], "symbolic link"));
    ASSERT_EQ(s.refused.count("06-geometry.glsl"), 1u);
    EXPECT_TRUE(contains(s.refused["06-geometry.glsl"], "not a regular file"));
    EXPECT_TRUE(fs::exists(dir / "staged" / "01-camera.glsl"));
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "staged" / "05-ggx.glsl")));
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "staged" / "helper.glsl")));
    std::string notes;
    for (const std::string& n : s.notes) notes += n + "\n";
    EXPECT_TRUE(contains(notes, "helper.glsl")) << notes;
}

TEST(Submissions, NestedFolderIsFoundAndExtraFilesIgnored) {
    Scratch scratch{freshTempDir("stage_nested")};
    const fs::path& dir = scratch.dir;
    writeFolder(dir / "me" / "raylab-main" / "exercises", {{"01-camera.glsl", "// one\n"}, {"lib/util.glsl", "// u\n"}});
    writeFolder(dir / "me", {{"README.md", "hi"}, {"photo.png", "png"}});
    StagedSubmission s = stageSubmission(folderEntry(dir / "me"), dir / "staged", dir / "scratch");
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None);
    EXPECT_TRUE(fs::exists(dir / "staged" / "01-camera.glsl"));
    EXPECT_TRUE(fs::exists(dir / "staged" / "lib" / "util.glsl")) << "includes in sub-folders come along";
    EXPECT_FALSE(fs::exists(dir / "staged" / "README.md"));
    ASSERT_GE(s.notes.size(), 2u);
    EXPECT_EQ(s.notes[0], "graded the folder raylab-main/exercises/ inside the submission");
    EXPECT_TRUE(contains(s.notes.back(), "README.md")) << s.notes.back();
}

TEST(Submissions, EmptyAndUnrelatedSubmissionsSayWhy) {
    Scratch scratch{freshTempDir("stage_empty")};
    const fs::path& dir = scratch.dir;
    fs::create_directories(dir / "empty");
    StagedSubmission e = stageSubmission(folderEntry(dir / "empty"), dir / "s1", dir / "x");
    EXPECT_EQ(e.problem, StagedSubmission::Problem::Empty);
    EXPECT_TRUE(contains(e.problemReason, "empty"));
    writeFolder(dir / "wrong", {{"homework.docx", "?"}});
    StagedSubmission w = stageSubmission(folderEntry(dir / "wrong"), dir / "s2", dir / "x");
    EXPECT_EQ(w.problem, StagedSubmission::Problem::Empty);
    EXPECT_TRUE(contains(w.problemReason, "homework.docx")) << w.problemReason;
}

TEST(Submissions, NonUtf8AndOversizedFilesAreRefusedWithTheirName) {
    Scratch scratch{freshTempDir("stage_bytes")};
    const fs::path& dir = scratch.dir;
    // Outside a comment (a byte in a comment is read as Windows-1252: test_lms_names.cpp).
    writeFolder(dir / "me", {{"03-lambert.glsl", "// ok\nfloat caf\xe9;\n"},
                             {"05-ggx.glsl", std::string(300 * 1024, '/')},
                             {"07-fresnel.glsl", std::string("nul\0byte", 8)}});
    StagedSubmission s = stageSubmission(folderEntry(dir / "me"), dir / "staged", dir / "scratch");
    EXPECT_EQ(s.refused["03-lambert.glsl"].rfind("03-lambert.glsl:2: file is not UTF-8 text: byte 0xE9", 0), 0u)
        << s.refused["03-lambert.glsl"];
    EXPECT_EQ(s.refused["05-ggx.glsl"], "05-ggx.glsl: file is 300 KiB, over the 256 KiB limit for a shader file");
    EXPECT_TRUE(contains(s.refused["07-fresnel.glsl"], "NUL")) << s.refused["07-fresnel.glsl"];
}

TEST(OutputFolder, OneRunAtATimeAndNeverInsideTheSubmissions) {
    Scratch scratch{freshTempDir("lock")};
    const fs::path& dir = scratch.dir;
    {
        FolderLock first(dir);
        EXPECT_TRUE(contains(refusalOf([&] { FolderLock second(dir); }), "another raylab grade is writing here"));
    }
    EXPECT_EQ(refusalOf([&] { FolderLock again(dir); }), "") << "released with its holder";
    EXPECT_TRUE(pathsOverlap(dir / "sub", dir / "sub" / "out"));
    EXPECT_TRUE(pathsOverlap(dir / "sub" / "out", dir / "sub"));
    EXPECT_TRUE(pathsOverlap(dir / "sub", dir / "sub" / "."));
    EXPECT_FALSE(pathsOverlap(dir / "sub", dir / "subway"));
}

// ---- rubric, CSV, shards --------------------------------------------------------------

TEST(Rubric, DefaultIsValidAndWorth100) {
    Rubric r = loadRubric(defaultRubricPath());
    EXPECT_EQ(r.exercises.size(), 12u);  // the optional 11-environment and 12-sky-shadows with weight 0: still worth 100
    EXPECT_EQ(r.maxHundredths(), 10000);
    EXPECT_EQ(r.idColumn, "Student");
}

TEST(Rubric, PointsFollowTheDocumentedFormula) {
    Rubric r = loadRubric(defaultRubricPath());
    const RubricExercise& ggx = r.exercises[4];  // 05-ggx, 10 points
    ASSERT_EQ(ggx.id, "05-ggx");
    ExerciseGrade g;
    g.report.id = "05-ggx";
    g.report.status = CheckStatus::Fail;
    g.report.probes = {{"D_GGX", 30, 40}};  // 0.75
    ImageSummary pass, nearly, far, nan;
    pass.passed = true;
    nearly.meanLsb = 2;  // 0.5 * (1 - 2/8) = 0.375
    far.meanLsb = 20;    // 0
    nan.meanLsb = 0.1;
    nan.nonFinite = 3;   // 0
    g.report.images = {pass, nearly, far, nan};
    // 10 * (0.5 * 0.75 + 0.5 * (1 + 0.375) / 4) = 5.46875 -> 5.47
    EXPECT_EQ(exerciseHundredths(r, ggx, &g), 547);
    g.report.status = CheckStatus::Pass;
    EXPECT_EQ(exerciseHundredths(r, ggx, &g), 1000);
    for (CheckStatus s : {CheckStatus::NotStarted, CheckStatus::CompileError, CheckStatus::TimedOut, CheckStatus::Crashed}) {
        g.report.status = s;
        EXPECT_EQ(exerciseHundredths(r, ggx, &g), 0) << statusName(s);
    }
    g.report.status = CheckStatus::Pass;
    g.refused = true;
    EXPECT_EQ(exerciseHundredths(r, ggx, &g), 0);
    EXPECT_EQ(exerciseHundredths(r, ggx, nullptr), 0);
    // A FAIL earns at most fail_max (0.75) of the weight, and never rounds up to full marks.
    g.refused = false;
    g.report.status = CheckStatus::Fail;
    g.report.probes = {{"D_GGX", 39, 40}};
    g.report.images = {pass, pass, pass, pass};
    EXPECT_EQ(exerciseHundredths(r, ggx, &g), 750);
    r.failMax = 1;
    g.report.probes = {{"D_GGX", 40, 40}};
    EXPECT_EQ(exerciseHundredths(r, ggx, &g), 999);
}

TEST(Rubric, BadRubricsNameTheFileAndTheProblem) {
    Scratch scratch{freshTempDir("rubric_bad")};
    const fs::path& dir = scratch.dir;
    auto check = [&](const std::string& text, const std::string& expected) {
        writeText(dir / "r.json", text);
        std::string why = refusalOf([&] { loadRubric(dir / "r.json"); });
        EXPECT_TRUE(contains(why, "r.json: ") && contains(why, expected)) << text << " -> " << why;
    };
    writeText(dir / "r.json", "{");  // a syntax error has a line and column (core/json_text.h)
    EXPECT_TRUE(contains(refusalOf([&] { loadRubric(dir / "r.json"); }), "r.json:1:2: syntax error"));
    check("{\"exercises\": []}", "non-empty array");
    check("{\"exercises\": [{\"id\": \"05-ggx\"}]}", "\"weight\" is missing");
    check("{\"exercises\": [{\"id\": \"5\", \"weight\": 1}, {\"id\": \"05-ggx\", \"weight\": 1}]}", "listed twice");
    check("{\"exercises\": [{\"id\": \"05-ggx\", \"weight\": -1}]}", ">= 0");
    check("{\"credit\": {\"probe_weight\": 0.7}, \"exercises\": [{\"id\": \"05-ggx\", \"weight\": 1}]}", "must be 1");
    check("{\"credit\": {\"fail_max\": 1.5}, \"exercises\": [{\"id\": \"05-ggx\", \"weight\": 1}]}", "at most 1");
    EXPECT_TRUE(contains(refusalOf([&] { loadRubric(dir / "missing.json"); }), "missing.json: rubric file not found"));
}

TEST(GradesCsv, QuotesOnlyWhatNeedsItAndFormatsFixed) {
    Rubric r;
    r.idColumn = "Username";
    r.exercises = {{"05-ggx", 7.5, "GGX, D"}};
    StudentGrade a, b;
    a.id = "zed";
    a.exercises.push_back({});
    a.exercises[0].report.id = "05-ggx";
    a.exercises[0].report.status = CheckStatus::Pass;
    b.id = "o\"neil, j";
    EXPECT_EQ(gradesCsv(r, {a, b}), "Username,\"GGX, D\",Total\n\"o\"\"neil, j\",0.00,0.00\nzed,7.50,7.50\n");
}

TEST(Shards, StableAndSpread) {
    EXPECT_EQ(shardOf("alice", 1), 1);
    std::set<int> seen;
    for (int k = 0; k < 200; ++k) {
        int s = shardOf("student" + std::to_string(k), 7);
        ASSERT_GE(s, 1);
        ASSERT_LE(s, 7);
        seen.insert(s);
    }
    EXPECT_EQ(seen.size(), 7u);
    EXPECT_EQ(shardOf("alice", 7), shardOf(std::string("ali") + "ce", 7));
}

// Issue 36: a student whose folder cannot be written stopped the class with
// "cannot write" and no outputs. Now it is listed, keeps its row, and every
// class file is written.
TEST(ClassOutputs, AStudentThatCannotBeWrittenDoesNotStopTheClass) {
    Scratch scratch{freshTempDir("unwritable")};
    const fs::path out = scratch.dir / "out";
    Rubric rubric = loadRubric(defaultRubricPath());
    std::vector<StudentGrade> grades(3);
    for (std::size_t k = 0; k < grades.size(); ++k) grades[k].id = std::string(1, char('a' + k));
    fs::create_directories(out);
    writeText(out / "b", "a file where b's folder would go");  // writing OUT/b/... fails: not a directory
    RunInfo info;
    info.submissionsTotal = 3;
    std::vector<std::string> failed = writeClassOutputs(out, rubric, grades, gradeSummary(rubric, grades, info));
    ASSERT_EQ(failed.size(), 1u);
    EXPECT_TRUE(contains(failed[0], "b/")) << failed[0];
    const nlohmann::json summary = nlohmann::json::parse(readText(out / "summary.json"));
    EXPECT_EQ(summary.at("students_not_written").size(), 1u);
    const std::string csv = readText(out / "grades.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
    EXPECT_EQ(readText(out / "students.txt"), "a\nb\nc\n");
    EXPECT_TRUE(fs::is_regular_file(out / "a" / "index.html"));
    EXPECT_TRUE(fs::is_regular_file(out / "c" / "index.html"));
    EXPECT_TRUE(contains(readText(out / "index.html"), "could not be written"));
}

TEST(Merge, RefusesMissingShardsDifferentRubricsAndTwiceGradedStudents) {
    Scratch scratch{freshTempDir("merge_bad")};
    const fs::path& dir = scratch.dir;
    Rubric rubric = loadRubric(defaultRubricPath());
    auto shard = [&](const std::string& name, int index, int count, const std::vector<std::string>& ids,
                     const Rubric& r) {
        std::vector<StudentGrade> grades;
        for (const std::string& id : ids) {
            StudentGrade g;
            g.id = id;
            saveStudentGrade(dir / name, g);
            grades.push_back(g);
        }
        RunInfo info;
        info.shardIndex = index;
        info.shardCount = count;
        info.submissionsTotal = 3;
        writeClassOutputs(dir / name, r, grades, gradeSummary(r, grades, info));
    };
    shard("s1", 1, 3, {"a"}, rubric);
    shard("s2", 2, 3, {"b"}, rubric);
    shard("s3", 3, 3, {"c"}, rubric);
    shard("s3b", 3, 3, {"b"}, rubric);
    Rubric other = rubric;
    other.idColumn = "Username";
    shard("s3r", 3, 3, {"c"}, other);
    std::ostringstream log;
    auto merge = [&](std::vector<fs::path> in) {
        return refusalOf([&] { mergeGradeOutputs(in, dir / "merged", log); });
    };
    EXPECT_TRUE(contains(merge({dir / "s1", dir / "s2"}), "shard 3/3 is missing"));
    EXPECT_TRUE(contains(merge({dir / "s1", dir / "s2", dir / "s3r"}), "same rubric"));
    EXPECT_TRUE(contains(merge({dir / "s1", dir / "s2", dir / "s3b"}), "student b was also graded"));
    EXPECT_TRUE(contains(merge({dir / "s1", dir / "s2", dir / "s1"}), "shard 1/3 is also"));
    EXPECT_TRUE(contains(merge({dir / "s1", dir / "nothing"}), "summary.json: missing") ||
                contains(merge({dir / "s1", dir / "nothing"}), "rubric.json: missing"));
    EXPECT_EQ(merge({dir / "s1", dir / "s2", dir / "s3"}), "");
    EXPECT_EQ(readText(dir / "merged" / "grades.csv").substr(0, 8), "Student,");
}

// ---- Gradescope's results.json from a rubric that asks for more ----------------------------

TEST(GradescopeResults, VisibilityOutputFormatAndLeaderboardFollowTheRubric) {
    nlohmann::json j = toJson(loadRubric(defaultRubricPath()));
    j["gradescope"] = {{"output_format", "md"}, {"visibility", "after_published"}, {"leaderboard", true}};
    j["exercises"][9]["visibility"] = "after_due_date";
    j["exercises"][8]["visibility"] = "hidden";
    Rubric r = rubricFromJson(j, "rubric.json");
    StudentGrade g;
    g.id = "alice";
    g.notes = {"graded the folder exercises/ inside the submission"};
    for (const RubricExercise& e : r.exercises) {
        ExerciseGrade x;
        x.report.id = e.id;
        x.report.status = CheckStatus::Fail;
        x.report.message = "image sphere-row: 3.00% of pixels off";
        x.report.hint = "the probes pass but the picture differs: compare alice/images/a-got.png with ../_reference/a.png";
        x.report.details = "  image sphere-row: 3.00% of pixels off\n    expected ../_reference/a.png\n"
                           "    got      images/a-got.png\n    diff     images/a-diff.png\n";
        ImageSummary image;
        image.scene = "sphere-row";
        image.meanLsb = 2.5;
        image.offFraction = 0.03;
        x.report.images = {image};
        g.exercises.push_back(x);
    }
    nlohmann::json results = gradescopeResults(r, g);
    EXPECT_EQ(results.at("output_format"), "md");
    EXPECT_EQ(results.at("visibility"), "after_published");
    EXPECT_EQ(results.at("tests")[9].at("visibility"), "after_due_date");
    EXPECT_EQ(results.at("tests")[8].at("visibility"), "hidden");
    EXPECT_EQ(results.at("tests")[0].at("visibility"), "visible");
    ASSERT_TRUE(results.contains("leaderboard"));
    EXPECT_EQ(results["leaderboard"][0].at("value"), results.at("score"));
    const std::string out = results["tests"][0].at("output").get<std::string>();
    EXPECT_FALSE(contains(out, ".png")) << "Gradescope keeps only results.json: " << out;
    EXPECT_TRUE(contains(out, "sphere-row: 3.00% of pixels off, mean error 2.50/255")) << out;
    EXPECT_TRUE(contains(out, "```")) << "the table stays a table in Markdown: " << out;
    j["exercises"][0]["visibility"] = "students";
    EXPECT_TRUE(contains(refusalOf([&] { rubricFromJson(j, "rubric.json"); }),
                         "rubric.json: exercises[0]: \"visibility\" must be one of"));
}
