// Where students' work comes from: one entry per student in SUBMISSIONS (a
// folder, a .zip, or the files an LMS bulk download gives one student, see
// grading/roster.h), and how it becomes a clean folder that the checker may
// read.
//
// The exercise files are searched for the way an instructor would: at any
// depth, inside zips (and zips inside those), skipping build folders and
// version control; the folder with the most exercises that are not the
// unchanged stub wins, exercises it lacks are taken from elsewhere, renamed
// copies ("05-ggx (1).glsl", "05-ggx.GLSL") stand in for missing names, and
// every such choice becomes a note for the student.
//
// Staging copies only regular shader files from the student's own entry into
// OUT/<id>/submission/ and grades that copy, so that grading never reads
// another student's work or the instructor's files: symbolic links are never
// followed (an exercise file that is a link is refused), zips are extracted
// by grading/safe_unzip.h, special files are skipped, and every exercise file
// is checked for size and UTF-8 before the checker sees it. The include
// resolver then keeps #include inside that copy.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rl {

struct SubmissionEntry {
    enum class Kind { Folder, Zip, Link, Group };
    std::string id;              // the entry's name; for a zip without ".zip"; for a Group its student ("doejane_12345")
    std::filesystem::path path;  // SUBMISSIONS/<name>; for a Group its first part
    Kind kind = Kind::Folder;
    // Group: the entries of an LMS download that belong to one student, each
    // with the name it stands for ("05-ggx.glsl" for
    // "doejane_12345_67890_05-ggx.glsl"; "" for a folder: its contents).
    std::vector<std::pair<std::filesystem::path, std::string>> parts;
};

struct SubmissionList {
    std::vector<SubmissionEntry> students;  // sorted by id, ids unique
    std::vector<std::string> ignored;       // entries that are no student, with the reason
};

// Every folder, .zip and symbolic link in `dir` is a student, and so is every
// group of entries named as an LMS bulk download names them (Canvas:
// "doejane_12345_67890_05-ggx.glsl", Moodle: "Jane Doe_12345_assignsubmission_file_");
// hidden entries and other files are listed as ignored. Throws rl::Error when `dir` is not a
// readable folder.
SubmissionList listSubmissions(const std::filesystem::path& dir);

// A digest of what the entry holds (names, file bytes, link targets; at
// most 64 MiB read), so that a later run regrades a submission that changed
// since it was graded, and only such a one.
std::string submissionFingerprint(const SubmissionEntry& entry);

struct StagedSubmission {
    enum class Problem { None, Empty, Refused };
    Problem problem = Problem::None;  // Empty: every exercise NOT STARTED; Refused: every exercise REFUSED
    std::string problemReason;        // one line for the student, when problem != None
    std::map<std::string, std::string> refused;  // exercise file ("05-ggx.glsl") -> why it was refused
    // Exercise files that could never finish on a GPU (a loop with a constant
    // true condition and no way out), found before compiling: TIMEOUT on
    // every machine, whatever llvmpipe's loop cap makes of them.
    std::map<std::string, std::string> endless;
    std::vector<std::string> notes;              // ignored and refused files, nesting: for the student
};

// Copies the entry's shader files into `stagingDir` (created; must not exist
// yet); `scratchDir` is used for a zip's contents and removed afterwards.
// Never throws for anything a student can cause: that becomes a problem,
// a refusal or a note.
StagedSubmission stageSubmission(const SubmissionEntry& entry, const std::filesystem::path& stagingDir,
                                 const std::filesystem::path& scratchDir);

}  // namespace rl
