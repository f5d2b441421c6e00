// Gradebook files that the LMS imports as they are (docs/grading.md,
// "Gradebook exports"), from the records of a finished run:
//
//   canvas  OUT/grades-canvas.csv: "Student","ID","SIS User ID","SIS Login ID",
//           "Section", one assignment column with the total, a "Points
//           Possible" row. Canvas's importer (GradebookImporter) makes every
//           other column an assignment unless its header holds "Current
//           Points" (or Score, Grade, ...): per-exercise columns, when asked
//           for, are named "<exercise> Current Points", which the importer
//           drops, and are marked "(read only)" in the points row, as in
//           Canvas's own export.
//   moodle  OUT/grades-moodle.csv: the identifier column (Username, ID
//           number or Email address: "Map from" in Moodle's CSV import), the
//           total under the grade item's name, per-exercise columns when asked
//           for (Moodle imports only the columns mapped to a grade item).
//           Moodle aborts the whole import on one unknown user, so only
//           students known to the roster are written, and the others are
//           listed before anything is imported.
//   csv     OUT/grades.csv, as every run writes it.
//
// With a roster (grading/roster.h) every submission is matched to its
// student, and the report lists students without a submission and
// submissions without a student.
#pragma once

#include "grading/rubric.h"
#include "grading/student_grade.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rl {

struct ExportOptions {
    std::string format;               // "canvas", "moodle" or "csv"
    std::filesystem::path roster;     // the LMS's own class export; empty: none
    std::string assignment;           // the assignment (Canvas) or grade item (Moodle) column; default: the roster's or the rubric's
    std::string moodleId = "username";  // username, idnumber or email
    bool exerciseColumns = false;     // per-exercise columns too (read-only in Canvas)
    std::filesystem::path output;     // default: OUT/grades-<format>.csv
};

struct ExportReport {
    std::filesystem::path file;                 // what was written
    std::size_t rows = 0;                       // students written
    std::vector<std::string> unmatched;         // submissions with no student: "id: why"
    std::vector<std::string> withoutSubmission; // roster students with no submission
    std::vector<std::string> notes;             // other things the instructor must know
};

// Checks the options of one export before anything is graded: the format,
// --moodle-id, and the roster (readable, and of the LMS the format is for).
// Throws rl::Error naming the option or the roster file.
void checkExportOptions(const ExportOptions& options);

// The roster students no graded submission matches ("Name (line N)"), and
// the submissions that match no roster student ("id: why"), as the export's
// report lists them.
void rosterCoverage(const std::filesystem::path& roster, const std::vector<StudentGrade>& grades,
                    std::vector<std::string>& withoutSubmission, std::vector<std::string>& unmatched);

// What the export does with Canvas's Test Student of a roster: "" when the
// roster has none.
std::string testStudentNote(const std::filesystem::path& roster);

// Writes the export from the students' records in OUT (as `raylab grade`
// leaves them). Throws rl::Error for a bad format, roster or OUT.
ExportReport exportGrades(const std::filesystem::path& out, const ExportOptions& options);

// The text of an export, for the records and rubric given (no files read).
std::string exportText(const Rubric& rubric, const std::vector<StudentGrade>& grades, const ExportOptions& options,
                       ExportReport& report);

// Prints the report: where the file is, then every problem, one per line.
void printExportReport(const ExportReport& report, const std::string& format, std::ostream& log);

}  // namespace rl
