// Gradebook exports and rosters, without a GPU: the Canvas and Moodle files
// are fed to models of the two importers, written from their documented
// rules (and, for Canvas, from GradebookImporter's code), with rosters in
// each LMS's own export format (tests/grading/fixtures/).
//
// Canvas (GradebookImporter): the header needs "Student" in column 0, "ID"
// in column 1, then "SIS User ID" and "SIS Login ID", and "Section" as the
// last student column; every other column becomes an assignment (a new one
// when neither its "(id)" nor its name is known) unless its header holds
// Current/Final Score/Points/Grade or Override Score/Grade/Status; a row whose
// first cell holds "Points Possible" describes the assignments; a student is
// found by ID, then SIS User ID, SIS Login ID, then name, and is otherwise a
// missing student.
// Moodle (grade/import/csv): one column is mapped to username, ID number or
// email; one value that matches no user stops the whole import.
#include "grading/class_fixture.h"
#include "support/test_support.h"

#include "core/error.h"
#include "core/paths.h"
#include "grading/grades_csv.h"
#include "grading/lms_export.h"
#include "grading/roster.h"
#include "grading/rubric.h"
#include "grading/student_grade.h"
#include "grading/submission.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <set>

namespace fs = std::filesystem;
using namespace rl;
using namespace rl::test;

namespace {

// A test's folder, removed when the test passes (kept to look at when it fails).
struct Scratch {
    fs::path dir;
    ~Scratch() {
        if (!::testing::Test::HasFailure()) fs::remove_all(dir);
    }
};

fs::path fixture(const std::string& name) { return sourceRoot() / "tests" / "grading" / "fixtures" / name; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

// A record whose first `passes` rubric exercises PASS and the rest are NOT STARTED.
StudentGrade graded(const Rubric& rubric, const std::string& id, const std::string& source, std::size_t passes) {
    StudentGrade g;
    g.id = id;
    g.source = source;
    for (std::size_t k = 0; k < rubric.exercises.size(); ++k) {
        ExerciseGrade e;
        e.report.id = rubric.exercises[k].id;
        e.report.status = k < passes ? CheckStatus::Pass : CheckStatus::NotStarted;
        g.exercises.push_back(e);
    }
    return g;
}

// ---- Canvas's importer, as a model -----------------------------------------------------

struct CanvasImport {
    std::string error;                            // the header was refused
    std::vector<std::string> newAssignments;      // columns that would create an assignment
    std::vector<std::string> knownAssignments;    // columns matched to an existing one
    std::vector<std::string> missingStudents;     // rows matching no student
    std::map<std::string, std::string> grades;    // Canvas ID -> the first assignment's cell
};

CanvasImport canvasImport(const std::string& csv, const Roster& course) {
    CanvasImport r;
    std::vector<std::vector<std::string>> rows = parseCsv(csv);
    if (rows.empty()) {
        r.error = "empty";
        return r;
    }
    const std::vector<std::string>& h = rows[0];
    if (!(h.size() > 3 && contains(h[0], "Student") && contains(h[1], "ID"))) {
        r.error = "Couldn't find header row";
        return r;
    }
    std::size_t studentColumns = 3;
    int sisUser = -1, sisLogin = -1;
    if (std::regex_search(h[2], std::regex(R"(SIS\s+Login\s+ID)"))) {
        sisLogin = 2;
        studentColumns += 1;
    } else if (std::regex_search(h[2], std::regex(R"(SIS\s+User\s+ID)")) &&
               std::regex_search(h[3], std::regex(R"(SIS\s+Login\s+ID)"))) {
        sisUser = 2;
        sisLogin = 3;
        studentColumns += 2 + (h.size() > 4 && std::regex_search(h[4], std::regex(R"(Integration\s+ID)")) ? 1 : 0);
    }
    if (!contains(h[studentColumns - 1], "Section")) {
        r.error = "Couldn't find header row (no Section)";
        return r;
    }
    static const std::regex nonAssignment(
        "Current Score|Current Points|Current Grade|Final Score|Final Points|Final Grade|Override Score|Override "
        "Grade|Override Status");
    std::set<std::string> existingIds, existingTitles;
    static const std::regex titleAndId(R"(^(.*) \((\d+)\)$)");
    for (const std::string& header : course.headers) {
        std::smatch m;
        if (std::regex_match(header, m, titleAndId)) {
            existingIds.insert(m[2]);
            existingTitles.insert(m[1]);
        }
    }
    std::vector<std::size_t> assignmentColumns;
    for (std::size_t k = studentColumns; k < h.size(); ++k) {
        if (std::regex_search(h[k], nonAssignment)) continue;
        assignmentColumns.push_back(k);
        std::smatch m;
        bool known = (std::regex_match(h[k], m, titleAndId) && existingIds.count(m[2])) || existingTitles.count(h[k]);
        (known ? r.knownAssignments : r.newAssignments).push_back(h[k]);
    }
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::vector<std::string>& row = rows[i];
        if (contains(row[0], "Points Possible")) continue;
        const RosterStudent* found = nullptr;
        for (const RosterStudent& s : course.students)
            if (s.canvasId == row[1] || (sisUser >= 0 && !row[std::size_t(sisUser)].empty() && s.sisUserId == row[std::size_t(sisUser)]) ||
                (sisLogin >= 0 && !row[std::size_t(sisLogin)].empty() && s.sisLoginId == row[std::size_t(sisLogin)]) ||
                s.name == row[0])
                found = &s;
        if (!found) {
            r.missingStudents.push_back(row[0]);
            continue;
        }
        if (!assignmentColumns.empty()) r.grades[found->canvasId] = row[assignmentColumns[0]];
    }
    return r;
}

// ---- Moodle's importer, as a model -----------------------------------------------------

// Returns the error that stops the import, or "" and the grades by user.
std::string moodleImport(const std::string& csv, const Roster& users, const std::string& mapTo,
                         std::map<std::string, std::string>& grades) {
    std::vector<std::vector<std::string>> rows = parseCsv(csv);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& value = rows[i][0];
        bool known = false;
        for (const RosterStudent& s : users.students)
            known = known || (mapTo == "username" ? s.username : mapTo == "useridnumber" ? s.idNumber : s.email) == value;
        if (!known) return "user mapping error: no user with " + mapTo + " \"" + value + "\"";
        grades[value] = rows[i][1];
    }
    return "";
}

}  // namespace

TEST(Roster, ReadsCanvasAndMoodleExportsAsDownloaded) {
    Roster canvas = loadRoster(fixture("canvas-gradebook-export.csv"));
    EXPECT_EQ(canvas.kind, Roster::Kind::Canvas);
    ASSERT_EQ(canvas.students.size(), 4u) << "the points row and Canvas's test student are not students";
    EXPECT_EQ(canvas.students[2].name, "O'Brien, Máire");
    EXPECT_EQ(canvas.students[2].sisLoginId, "mobrien");
    EXPECT_EQ(canvas.students[3].section, "Graphics 101 B");

    Roster worksheet = loadRoster(fixture("moodle-grading-worksheet.csv"));  // BOM and CRLF, as Moodle writes it
    EXPECT_EQ(worksheet.kind, Roster::Kind::Moodle);
    ASSERT_EQ(worksheet.students.size(), 4u);
    EXPECT_EQ(worksheet.students[0].participantId, "4201");
    EXPECT_EQ(worksheet.students[0].email, "jane.doe@uni.example");

    Roster grades = loadRoster(fixture("moodle-grades-export.csv"));
    ASSERT_EQ(grades.students.size(), 4u);
    EXPECT_EQ(grades.students[1].name, "John Smith");
    EXPECT_EQ(grades.students[1].username, "jsmith");
    EXPECT_EQ(grades.students[1].idNumber, "20260002");

    Scratch scratch{freshTempDir("roster_bad")};
    writeText(scratch.dir / "class.csv", "Name,Mark\nx,1\n");
    try {
        loadRoster(scratch.dir / "class.csv");
        ADD_FAILURE() << "a file that is no roster is refused";
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "class.csv: not a roster")) << e.what();
    }
}

TEST(Roster, LmsDownloadNamesAreTakenApart) {
    LmsDownloadName c = parseLmsDownloadName("doejane_LATE_1001_98765_05-ggx-1.glsl");
    EXPECT_EQ(c.kind, LmsDownloadName::Kind::Canvas);
    EXPECT_EQ(c.student, "doejane_1001");
    EXPECT_EQ(c.file, "05-ggx-1.glsl");
    EXPECT_TRUE(c.late);
    LmsDownloadName m = parseLmsDownloadName("Jane Doe_4201_assignsubmission_file_");
    EXPECT_EQ(m.kind, LmsDownloadName::Kind::Moodle);
    EXPECT_EQ(m.student, "Jane Doe_4201");
    EXPECT_EQ(m.file, "");
    EXPECT_EQ(parseLmsDownloadName("Jane Doe_4201_assignsubmission_file_05-ggx.glsl").file, "05-ggx.glsl");
    EXPECT_EQ(parseLmsDownloadName("alice").kind, LmsDownloadName::Kind::None);
    EXPECT_EQ(parseLmsDownloadName("exercises_2").kind, LmsDownloadName::Kind::None);
}

TEST(CanvasExport, ImportsIntoTheExistingAssignmentWithEveryStudentFound) {
    Rubric rubric = loadRubric(defaultRubricPath());
    Roster course = loadRoster(fixture("canvas-gradebook-export.csv"));
    std::vector<StudentGrade> grades = {
        graded(rubric, "doejane_1001", "doejane_1001_555_exercises.zip", 10),  // a Canvas download: 100 points
        graded(rubric, "jsmith", "jsmith", 2),                                  // a folder named by SIS login: 18
        graded(rubric, "S0003", "S0003.zip", 0),                                // by SIS user id: 0
        graded(rubric, "zed", "zed", 5),                                        // nobody's
    };
    for (bool exerciseColumns : {false, true}) {
        ExportOptions o;
        o.format = "canvas";
        o.roster = fixture("canvas-gradebook-export.csv");
        o.assignment = "Ray tracer";
        o.exerciseColumns = exerciseColumns;
        ExportReport report;
        std::string csv = exportText(rubric, grades, o, report);
        CanvasImport imported = canvasImport(csv, course);
        EXPECT_EQ(imported.error, "") << csv;
        EXPECT_EQ(imported.newAssignments, std::vector<std::string>{}) << "no column may create an assignment\n" << csv;
        EXPECT_EQ(imported.knownAssignments, std::vector<std::string>{"Ray tracer (12345)"}) << csv;
        EXPECT_EQ(imported.missingStudents, std::vector<std::string>{}) << csv;
        EXPECT_EQ(imported.grades, (std::map<std::string, std::string>{{"1001", "100.00"}, {"1002", "18.00"}, {"1003", "0.00"}}));
        ASSERT_EQ(report.unmatched.size(), 1u);
        EXPECT_TRUE(contains(report.unmatched[0], "zed: no student of the roster")) << report.unmatched[0];
        EXPECT_EQ(report.withoutSubmission, std::vector<std::string>{"Lee, Ann (line 6)"});
        EXPECT_EQ(parseCsv(csv)[0][0], "Student");
        EXPECT_EQ(parseCsv(csv)[0][1], "ID");
    }
    // The plain CSV, as every run writes it, is no Canvas import: the model refuses it.
    EXPECT_NE(canvasImport(gradesCsv(rubric, grades), course).error, "");
}

TEST(CanvasExport, WithoutRosterOnlyCanvasDownloadsHaveAnId) {
    Rubric rubric = loadRubric(defaultRubricPath());
    Roster course = loadRoster(fixture("canvas-gradebook-export.csv"));
    std::vector<StudentGrade> grades = {graded(rubric, "doejane_1001", "doejane_1001_555_05-ggx.glsl", 1),
                                        graded(rubric, "alice", "alice", 1)};
    ExportOptions o;
    o.format = "canvas";
    o.assignment = "Ray tracer (12345)";
    ExportReport report;
    std::string csv = exportText(rubric, grades, o, report);
    CanvasImport imported = canvasImport(csv, course);
    EXPECT_EQ(imported.newAssignments, std::vector<std::string>{});
    EXPECT_EQ(imported.missingStudents, std::vector<std::string>{});
    EXPECT_EQ(imported.grades, (std::map<std::string, std::string>{{"1001", "8.00"}}));
    ASSERT_EQ(report.unmatched.size(), 1u);
    EXPECT_TRUE(contains(report.unmatched[0], "alice: no Canvas user id")) << report.unmatched[0];
}

TEST(MoodleExport, OnlyKnownIdsAreWrittenAndTheOthersListed) {
    Rubric rubric = loadRubric(defaultRubricPath());
    Roster users = loadRoster(fixture("moodle-grades-export.csv"));
    std::vector<StudentGrade> grades = {
        graded(rubric, "John Smith_4202", "John Smith_4202_assignsubmission_file_", 10),  // a Moodle download, by name
        graded(rubric, "jdoe", "jdoe", 1),                                                // by username
        graded(rubric, "20260003", "20260003.zip", 2),                                    // by ID number
        graded(rubric, "Jane Doe_4201", "Jane Doe_4201_assignsubmission_file_", 3),       // Jane again: left out, said
        graded(rubric, "zed", "zed", 4),                                                  // nobody's
    };
    for (const auto& [moodleId, mapTo] : std::vector<std::pair<std::string, std::string>>{
             {"username", "username"}, {"idnumber", "useridnumber"}, {"email", "useremail"}}) {
        ExportOptions o;
        o.format = "moodle";
        o.roster = fixture("moodle-grades-export.csv");
        o.assignment = "Ray tracer";
        o.moodleId = moodleId;
        ExportReport report;
        std::string csv = exportText(rubric, grades, o, report);
        std::map<std::string, std::string> imported;
        EXPECT_EQ(moodleImport(csv, users, mapTo, imported), "") << csv;
        EXPECT_EQ(imported.size(), 3u) << csv;
        EXPECT_EQ(report.unmatched.size(), 2u) << joined(report.unmatched);
        EXPECT_TRUE(contains(joined(report.unmatched), "zed: no student")) << joined(report.unmatched);
        EXPECT_TRUE(contains(joined(report.unmatched), "jdoe: the roster's student on line 2")) << joined(report.unmatched);
        EXPECT_EQ(report.withoutSubmission, std::vector<std::string>{"Ann Lee (line 5)"});
        EXPECT_EQ(parseCsv(csv)[0][1], "Ray tracer");
    }
    // Without a roster the ids are not checked: the model shows what Moodle does with one unknown id.
    ExportOptions plain;
    plain.format = "moodle";
    ExportReport report;
    std::string csv = exportText(rubric, grades, plain, report);
    std::map<std::string, std::string> imported;
    EXPECT_TRUE(contains(moodleImport(csv, users, "username", imported), "user mapping error")) << csv;
    EXPECT_EQ(report.unmatched.size(), 2u) << "the download names are never written as usernames";
}

TEST(MoodleExport, WorksheetRosterMatchesParticipantIds) {
    Rubric rubric = loadRubric(defaultRubricPath());
    Roster worksheet = loadRoster(fixture("moodle-grading-worksheet.csv"));
    std::vector<StudentGrade> grades = {graded(rubric, "Jane Doe_4201", "Jane Doe_4201_assignsubmission_file_", 10),
                                        graded(rubric, "M O Brien_4203", "M O Brien_4203_assignsubmission_file_", 1)};
    ExportOptions o;
    o.format = "moodle";
    o.roster = fixture("moodle-grading-worksheet.csv");
    o.moodleId = "email";
    ExportReport report;
    std::string csv = exportText(rubric, grades, o, report);
    std::map<std::string, std::string> imported;
    EXPECT_EQ(moodleImport(csv, worksheet, "useremail", imported), "") << csv;
    EXPECT_EQ(imported, (std::map<std::string, std::string>{{"jane.doe@uni.example", "100.00"},
                                                            {"maire.obrien@uni.example", "8.00"}}));
    // The worksheet has no usernames: every student is listed, none written.
    o.moodleId = "username";
    ExportReport none;
    exportText(rubric, grades, o, none);
    EXPECT_EQ(none.rows, 0u);
    EXPECT_EQ(none.unmatched.size(), 2u);
}

TEST(LmsDownloads, CanvasFilesAndMoodleFoldersBecomeOneSubmissionEach) {
    Scratch scratch{freshTempDir("lms_list")};
    const fs::path& dir = scratch.dir;
    std::map<std::string, std::string> solutions = solutionFiles();
    writeText(dir / "doejane_1001_501_01-camera.glsl", solutions["01-camera.glsl"]);
    writeText(dir / "doejane_1001_502_05-ggx-1.glsl", solutions["05-ggx.glsl"]);  // Canvas's name for a second upload
    writeText(dir / "doejane_LATE_1001_503_02-intersect.glsl", solutions["02-intersect.glsl"]);
    writeZip(dir / "smithjohn_1002_601_exercises.zip", {{"exercises/03-lambert.glsl", solutions["03-lambert.glsl"]}});
    writeFolder(dir / "Jane Doe_4201_assignsubmission_file_", {{"04-shadows.glsl", solutions["04-shadows.glsl"]}});
    writeFolder(dir / "Jane Doe_4201_assignsubmission_onlinetext_", {{"onlinetext.html", "<p>done</p>"}});
    writeText(dir / "roster.csv", "");
    writeFolder(dir / "lab_1_2_final", {{"01-camera.glsl", solutions["01-camera.glsl"]}});  // a folder: no Canvas name
    SubmissionList list = listSubmissions(dir);
    std::vector<std::string> ids;
    for (const SubmissionEntry& e : list.students) ids.push_back(e.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"Jane Doe_4201", "doejane_1001", "lab_1_2_final", "smithjohn_1002"}));
    ASSERT_EQ(list.students.size(), 4u);
    EXPECT_EQ(list.students[1].parts.size(), 3u);
    Scratch work{freshTempDir("lms_staged")};
    StagedSubmission s = stageSubmission(list.students[1], work.dir / "canvas", work.dir / "scratch");
    EXPECT_EQ(s.problem, StagedSubmission::Problem::None);
    EXPECT_EQ(readText(work.dir / "canvas" / "05-ggx.glsl"), solutions["05-ggx.glsl"]);
    EXPECT_TRUE(fs::exists(work.dir / "canvas" / "02-intersect.glsl"));
    EXPECT_TRUE(contains(joined(s.notes), "graded 05-ggx-1.glsl as 05-ggx.glsl")) << joined(s.notes);
    StagedSubmission moodle = stageSubmission(list.students[0], work.dir / "moodle", work.dir / "scratch");
    EXPECT_EQ(moodle.problem, StagedSubmission::Problem::None) << moodle.problemReason;
    EXPECT_TRUE(fs::exists(work.dir / "moodle" / "04-shadows.glsl"));
}

TEST(GradeExportCli, WritesTheFileAndListsWhatWasLeftOut) {
    Scratch scratch{freshTempDir("export_cli")};
    const fs::path out = scratch.dir / "out";
    Rubric rubric = loadRubric(defaultRubricPath());
    std::vector<StudentGrade> grades = {graded(rubric, "jdoe", "jdoe", 10), graded(rubric, "zed", "zed", 1)};
    nlohmann::json ids = nlohmann::json::array();
    for (const StudentGrade& g : grades) {
        saveStudentGrade(out, g);
        ids.push_back(g.id);
    }
    writeText(out / "rubric.json", toJson(rubric).dump(2));
    writeText(out / "students.txt", "jdoe\nzed\n");  // the export reads the ids there, never summary.json
    CommandResult r = runRaylab("grade export " + out.string() + " --format moodle --roster " +
                                fixture("moodle-grades-export.csv").string() + " --assignment 'Ray tracer'");
    EXPECT_EQ(r.status, 3) << "a submission was left out: " << r.output;
    EXPECT_TRUE(contains(r.output, "zed: no student of the roster")) << r.output;
    EXPECT_TRUE(contains(r.output, "3 students of the roster without a submission")) << r.output;
    EXPECT_EQ(readText(out / "grades-moodle.csv"), "Username,Ray tracer\njdoe,100.00\n");
    EXPECT_TRUE(contains(readText(out / "grades-moodle.report.txt"), "zed"));
    CommandResult bad = runRaylab("grade export " + out.string() + " --format blackboard");
    EXPECT_NE(bad.status, 0);
}
