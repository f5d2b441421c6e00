#include "grading/lms_export.h"

#include "core/error.h"
#include "core/message.h"
#include "grading/atomic_file.h"
#include "grading/grades_csv.h"
#include "grading/roster.h"
#include "grading/student_list.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace rl {

namespace {

std::string row(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t k = 0; k < fields.size(); ++k) out += (k ? "," : "") + csvField(fields[k]);
    return out + "\n";
}

// The assignment's header: a roster column "NAME (12345)" when there is one
// (Canvas then matches the assignment by its id), else NAME.
std::string canvasAssignmentHeader(const std::optional<Roster>& roster, const std::string& name) {
    if (roster && roster->kind == Roster::Kind::Canvas) {
        static const std::regex withId(R"(^(.*) \((\d+)\)$)");
        for (const std::string& h : roster->headers) {
            std::smatch m;
            if (h == name || (std::regex_match(h, m, withId) && m[1] == name)) return h;
        }
    }
    return name;
}

struct Matched {
    const StudentGrade* grade;
    const RosterStudent* student;  // nullptr without a roster
};

}  // namespace

namespace {

std::optional<Roster> checkedRoster(const ExportOptions& o) {
    if (o.format != "canvas" && o.format != "moodle" && o.format != "csv")
        throw Error("--format: expected canvas, moodle or csv, got " + quotedValue(o.format));
    if (o.format == "csv") return std::nullopt;
    if (o.moodleId != "username" && o.moodleId != "idnumber" && o.moodleId != "email")
        throw Error("--moodle-id: expected username, idnumber or email, got " + quotedValue(o.moodleId));
    std::optional<Roster> roster;
    if (!o.roster.empty()) roster = loadRoster(o.roster);
    if (roster && o.format == "canvas" && roster->kind != Roster::Kind::Canvas)
        throw Error(o.roster.string() + ": a Moodle roster; the Canvas export needs Canvas's gradebook export as roster");
    if (roster && o.format == "moodle" && roster->kind != Roster::Kind::Moodle)
        throw Error(o.roster.string() + ": a Canvas roster; the Moodle export needs a Moodle export as roster");
    return roster;
}

}  // namespace

void checkExportOptions(const ExportOptions& options) { checkedRoster(options); }

void rosterCoverage(const fs::path& rosterFile, const std::vector<StudentGrade>& grades,
                    std::vector<std::string>& withoutSubmission, std::vector<std::string>& unmatched) {
    const Roster roster = loadRoster(rosterFile);
    std::vector<bool> taken(roster.students.size(), false);
    for (const StudentGrade& g : grades) {
        std::string why;
        const int k = matchRosterStudent(roster, g.id, g.source, why);
        if (k < 0)
            unmatched.push_back(g.id + ": " + why);
        else
            taken[std::size_t(k)] = true;
    }
    for (std::size_t k = 0; k < roster.students.size(); ++k)
        if (!taken[k])
            withoutSubmission.push_back(roster.students[k].name + " (" + rosterFile.filename().string() + " line " +
                                        std::to_string(roster.students[k].line) + ")");
}

std::string testStudentNote(const fs::path& rosterFile) {
    const Roster roster = loadRoster(rosterFile);
    if (roster.testStudentLine == 0) return "";
    return "Canvas's Test Student (" + rosterFile.filename().string() + " line " +
           std::to_string(roster.testStudentLine) +
           ") is the course's preview account, not a student: left out of the export and of the roster checks; "
           "a submission of its own is graded and listed like any other";
}

std::string exportText(const Rubric& rubric, const std::vector<StudentGrade>& grades, const ExportOptions& o,
                       ExportReport& report) {
    std::optional<Roster> roster = checkedRoster(o);
    if (o.format == "csv") {
        report.rows = grades.size();
        return gradesCsv(rubric, grades);
    }

    std::vector<const StudentGrade*> sorted;
    for (const StudentGrade& g : grades) sorted.push_back(&g);
    std::sort(sorted.begin(), sorted.end(), [](const StudentGrade* a, const StudentGrade* b) { return a->id < b->id; });

    // Each submission's student; a student matched twice keeps the first submission.
    std::vector<Matched> matched;
    std::map<const RosterStudent*, const StudentGrade*> taken;
    for (const StudentGrade* g : sorted) {
        if (!roster) {
            matched.push_back({g, nullptr});
            continue;
        }
        std::string why;
        int k = matchRosterStudent(*roster, g->id, g->source, why);
        if (k < 0) {
            report.unmatched.push_back(g->id + ": " + why);
            continue;
        }
        const RosterStudent* s = &roster->students[std::size_t(k)];
        if (taken.count(s)) {
            report.unmatched.push_back(g->id + ": the roster's student on line " + std::to_string(s->line) + " (" +
                                       s->name + ") was already matched by the submission " + taken[s]->id +
                                       "; left out");
            continue;
        }
        taken[s] = g;
        matched.push_back({g, s});
    }
    if (roster)
        for (const RosterStudent& s : roster->students)
            if (!taken.count(&s))
                report.withoutSubmission.push_back(s.name + " (line " + std::to_string(s.line) + ")");
    if (roster && roster->testStudentLine)
        report.notes.push_back("Canvas's Test Student (line " + std::to_string(roster->testStudentLine) +
                               ") is the course's preview account: left out of the export");

    const std::string assignment = o.assignment.empty() ? rubric.totalColumn : o.assignment;
    std::string text;
    if (o.format == "canvas") {
        std::vector<std::string> header = {"Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                                           canvasAssignmentHeader(roster, assignment)};
        std::vector<std::string> points = {"    Points Possible", "", "", "", "", formatPoints(rubric.maxHundredths())};
        for (const RubricExercise& e : rubric.exercises)
            if (o.exerciseColumns) {
                header.push_back(e.column + " Current Points");
                points.push_back("(read only)");
            }
        text = row(header) + row(points);
        for (const Matched& m : matched) {
            std::vector<std::string> fields;
            if (m.student) {
                fields = {m.student->name, m.student->canvasId, m.student->sisUserId, m.student->sisLoginId,
                          m.student->section};
            } else {
                LmsDownloadName n = parseLmsDownloadName(m.grade->source);
                static const std::regex grouped(R"(^([\s\S]*)_(\d+)$)");
                std::smatch g;
                if (n.kind != LmsDownloadName::Kind::Canvas && std::regex_match(m.grade->id, g, grouped)) {
                    n.kind = LmsDownloadName::Kind::Canvas;
                    n.name = g[1];
                    n.number = g[2];
                }
                if (n.anonymous) {
                    report.unmatched.push_back(m.grade->id +
                                               ": an anonymous Canvas download (anon_<id>): Canvas gives no user id; "
                                               "import these grades in SpeedGrader, or turn anonymity off and download again");
                    continue;
                }
                if (n.kind != LmsDownloadName::Kind::Canvas) {
                    report.unmatched.push_back(m.grade->id +
                                               ": no Canvas user id in its name; give Canvas's gradebook export "
                                               "with --roster");
                    continue;
                }
                fields = {n.name, n.number, "", "", ""};
            }
            StudentScore s = scoreStudent(rubric, *m.grade);
            fields.push_back(formatPoints(s.total));
            if (o.exerciseColumns)
                for (long h : s.hundredths) fields.push_back(formatPoints(h));
            text += row(fields);
            ++report.rows;
        }
    } else {
        const std::string idHeader = o.moodleId == "username" ? "Username"
                                     : o.moodleId == "idnumber" ? "ID number"
                                                                : "Email address";
        std::vector<std::string> header = {idHeader, assignment};
        if (o.exerciseColumns)
            for (const RubricExercise& e : rubric.exercises) header.push_back(e.column);
        text = row(header);
        for (const Matched& m : matched) {
            std::string id;
            if (m.student) {
                id = o.moodleId == "username" ? m.student->username
                     : o.moodleId == "idnumber" ? m.student->idNumber
                                                : m.student->email;
                if (startsLikeFormula(id)) {
                    report.unmatched.push_back(m.grade->id + ": the " + idHeader + " of " + m.student->name +
                                               " (line " + std::to_string(m.student->line) +
                                               ") starts like a spreadsheet formula; written with a leading ' Moodle "
                                               "would not find the user and stop the import: choose another --moodle-id");
                    continue;
                }
                if (id.empty()) {
                    report.unmatched.push_back(m.grade->id + ": the roster has no " + idHeader + " for " +
                                               m.student->name + " (line " + std::to_string(m.student->line) +
                                               "); export a roster with that column, or choose another --moodle-id");
                    continue;
                }
            } else {
                if (parseLmsDownloadName(m.grade->source).kind != LmsDownloadName::Kind::None) {
                    report.unmatched.push_back(m.grade->id + ": a Moodle download name, not a " + idHeader +
                                               "; give a Moodle export with --roster");
                    continue;
                }
                id = m.grade->id;
                if (startsLikeFormula(id)) {
                    report.unmatched.push_back(m.grade->id + ": starts like a spreadsheet formula; not a " + idHeader +
                                               " Moodle knows: give a Moodle export with --roster");
                    continue;
                }
            }
            StudentScore s = scoreStudent(rubric, *m.grade);
            std::vector<std::string> fields = {id, formatPoints(s.total)};
            if (o.exerciseColumns)
                for (long h : s.hundredths) fields.push_back(formatPoints(h));
            text += row(fields);
            ++report.rows;
        }
        if (!roster)
            report.notes.push_back("no --roster: the ids were not checked; Moodle stops the whole import at the first "
                                   "id it does not know");
    }
    return text;
}

ExportReport exportGrades(const fs::path& out, const ExportOptions& options) {
    std::error_code ec;
    if (!fs::is_regular_file(studentListPath(out), ec) || !fs::is_regular_file(out / "rubric.json", ec))
        throw Error(out.string() + ": not the output of a finished `raylab grade` (no students.txt or rubric.json; "
                    "an output of an older raylab gets them from the same grade command again, which grades no one twice)");
    nlohmann::json rubricJson;
    try {
        rubricJson = nlohmann::json::parse(readWholeFile(out / "rubric.json"));
    } catch (const nlohmann::json::exception& e) {
        throw Error((out / "rubric.json").string() + ": not valid JSON (" + e.what() + ")");
    }
    Rubric rubric = rubricFromJson(rubricJson, (out / "rubric.json").string());
    std::vector<StudentGrade> grades;
    // One record at a time, from the list of ids: no file of the class as a whole is read.
    for (const std::string& id : readStudentList(out)) {
        std::optional<StudentGrade> g = loadStudentGrade(out, id);
        if (!g) throw Error(gradeRecordPath(out, id).string() + ": missing or unreadable");
        grades.push_back(*g);
    }
    ExportReport report;
    std::string text = exportText(rubric, grades, options, report);
    report.file = !options.output.empty()      ? options.output
                  : options.format == "csv" ? out / "grades.csv"
                                            : out / ("grades-" + options.format + ".csv");
    writeFileAtomic(report.file, text);
    if (options.format != "csv") {
        // The same lines as on the terminal, kept beside the file for a batch run's instructor.
        std::ostringstream lines;
        printExportReport(report, options.format, lines);
        fs::path beside = report.file;
        beside.replace_extension(".report.txt");
        writeFileAtomic(beside, lines.str());
    }
    return report;
}

void printExportReport(const ExportReport& report, const std::string& format, std::ostream& log) {
    log << format << " export: " << report.rows << " student" << (report.rows == 1 ? "" : "s") << " in "
        << report.file.string() << "\n";
    if (!report.unmatched.empty()) {
        log << report.unmatched.size() << " submission" << (report.unmatched.size() == 1 ? "" : "s")
            << " left out of the export (fix them before importing):\n";
        for (const std::string& u : report.unmatched) log << "  " << printable(u, 500) << "\n";
    }
    if (!report.withoutSubmission.empty()) {
        log << report.withoutSubmission.size() << " student" << (report.withoutSubmission.size() == 1 ? "" : "s")
            << " of the roster without a submission (not in the export):\n";
        for (const std::string& s : report.withoutSubmission) log << "  " << printable(s, 500) << "\n";
    }
    for (const std::string& n : report.notes) log << "note: " << printable(n, 500) << "\n";
}

}  // namespace rl
