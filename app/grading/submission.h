// Where students' work comes from: one entry per student in SUBMISSIONS (a
// folder, possibly a copy of exercises/ nested a level or two deeper, or a
// .zip of one), and how it becomes a clean folder that the checker may read.
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
    enum class Kind { Folder, Zip, Link };
    std::string id;              // the entry's name; for a zip without ".zip"
    std::filesystem::path path;  // SUBMISSIONS/<name>
    Kind kind = Kind::Folder;
};

struct SubmissionList {
    std::vector<SubmissionEntry> students;  // sorted by id, ids unique
    std::vector<std::string> ignored;       // entries that are no student, with the reason
};

// Every folder, .zip and symbolic link in `dir` is a student; hidden entries
// and other files are listed as ignored. Throws rl::Error when `dir` is not a
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
    std::vector<std::string> notes;              // ignored and refused files, nesting: for the student
};

// Copies the entry's shader files into `stagingDir` (created; must not exist
// yet); `scratchDir` is used for a zip's contents and removed afterwards.
// Never throws for anything a student can cause: that becomes a problem,
// a refusal or a note.
StagedSubmission stageSubmission(const SubmissionEntry& entry, const std::filesystem::path& stagingDir,
                                 const std::filesystem::path& scratchDir);

}  // namespace rl
