// The class list from the LMS itself, and how a submission's name finds its
// student in it.
//
// A roster is the LMS's own export, read as it is downloaded:
//   - Canvas: the gradebook export (Grades > Export): "Student", "ID",
//     "SIS User ID", "SIS Login ID", ["Integration ID"], "Section", then
//     assignment columns; a "Points Possible" row and Canvas's "Test Student"
//     are not students.
//   - Moodle: the grading worksheet of an assignment ("Identifier" =
//     "Participant 12345", "Full name", "Email address", ...), the gradebook
//     export ("First name", "Last name", "ID number", "Email address", ...), or
//     the participants table ("First name", "Last name", "Username", ...).
//
// Submission names: a folder or zip named after the student (any of the
// roster's ids), or the names the LMS's bulk download gives:
//   - Canvas: "doejane_12345_67890_05-ggx.glsl" (sortable name without
//     punctuation, the Canvas user id, the file id, the file's own name;
//     "_LATE" after the name for a late submission), one file each; the
//     name keeps Unicode letters ("müllerjürgen_1005_70021_01-camera.glsl");
//     with anonymous grading "anon_<anonymous id>_<file id>_<file name>"
//     ("LATE_anon_..." when late), which no roster can match;
//   - Moodle: "Jane Doe_12345_assignsubmission_file_" (full name, the
//     participant id of this assignment, the plugin), a folder each, or
//     "Jane Doe_12345_assignsubmission_file_05-ggx.glsl" without folders.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rl {

struct RosterStudent {
    std::string name;           // as the LMS shows it ("Doe, Jane" in Canvas, "Jane Doe" in Moodle)
    std::string canvasId;       // Canvas "ID"
    std::string sisUserId;      // Canvas "SIS User ID"
    std::string sisLoginId;     // Canvas "SIS Login ID"
    std::string section;        // Canvas "Section"
    std::string participantId;  // Moodle worksheet "Participant 12345" -> "12345"
    std::string username;       // Moodle "Username"
    std::string idNumber;       // Moodle "ID number"
    std::string email;          // Moodle "Email address"
    int line = 0;               // line in the roster file
};

struct Roster {
    enum class Kind { Canvas, Moodle };
    Kind kind = Kind::Canvas;
    std::filesystem::path file;
    std::vector<RosterStudent> students;
    std::vector<std::string> headers;  // the header row as read (Canvas: assignment columns "Name (id)")
    int testStudentLine = 0;           // Canvas's "Test Student" row, left out (0: none)
};

// Reads a roster (UTF-8, a byte-order mark allowed, comma or semicolon
// separated). Throws rl::Error "FILE: what is wrong" (or "FILE:LINE: ...").
Roster loadRoster(const std::filesystem::path& file);

// RFC 4180 rows of a CSV text (quotes, doubled quotes, CRLF), with `sep` as separator.
std::vector<std::vector<std::string>> parseCsv(const std::string& text, char sep = ',');

// A name from an LMS bulk download, taken apart.
struct LmsDownloadName {
    enum class Kind { None, Canvas, Moodle };
    Kind kind = Kind::None;
    std::string student;  // "doejane_12345" / "Jane Doe_12345": one student's group of files
    std::string name;     // "doejane" / "Jane Doe"
    std::string number;   // Canvas user id / Moodle participant id
    std::string file;     // the file's own name ("" for a Moodle folder)
    bool late = false;    // Canvas "_LATE" ("LATE_" before "anon_")
    bool anonymous = false;  // Canvas anonymous grading: "anon_<id>"; number is that id, there is no name
};
LmsDownloadName parseLmsDownloadName(const std::string& entryName);

// Which roster student a graded submission is: `id` is its name in OUT,
// `source` the entry it came from. Returns the index in roster.students, or
// -1 with `why` set (no such student, or more than one could be meant).
int matchRosterStudent(const Roster& roster, const std::string& id, const std::string& source, std::string& why);

}  // namespace rl
