// The name of an entry of SUBMISSIONS as a safe id. A file system name is
// any bytes but '/' and NUL; an LMS writes UTF-8 (Canvas keeps Unicode
// letters, Moodle full names), a zip made on Windows may carry CP-1252 or
// CP-437 bytes, and a hostile name may carry terminal escapes. An id is
// written into JSON (which must be UTF-8), HTML, CSV and folder names in
// OUT, and shown on the terminal, so a name that is not plain UTF-8 text
// becomes an escaped id ("caf%E9") while its original bytes are kept
// (as hex) for the export and the instructor.
#pragma once

#include <cstddef>
#include <string>

namespace rl {

// Valid UTF-8 (no overlong forms, no surrogates) without control
// characters (C0, DEL, C1) or bidirectional controls (U+202E, ...): a name
// that can be written anywhere as it is and reads as its bytes.
bool isPlainUtf8(const std::string& name);

// The longest id: a file name may have 255 bytes, and OUT/<id>/ and its
// staging names ("<id>.merging", "<id>-2") need room beside it.
constexpr std::size_t kMaxEntryIdBytes = 100;

// The name itself when isPlainUtf8; otherwise every byte that is not part of
// plain UTF-8 text, and '%', as "%XX" (upper-case hex). Longer than
// kMaxEntryIdBytes: cut, and "~" with 16 hex digits of a hash of the whole
// name appended. Stable, unique for distinct names, valid UTF-8, at most
// kMaxEntryIdBytes bytes, without control or bidirectional characters.
std::string safeEntryId(const std::string& name);

// Whether OUT/<id> would be one of the grader's own files or folders
// (grades.csv, index.html, summary.json, rubric.json, students.txt,
// _reference, .lock, .shader-cache, any grades-* export, a *.merging copy,
// "." and ".."). A submission with such a name is graded as
// graderSafeId(id): no name a student gives stops the run or an export.
bool isGraderOutputName(const std::string& id);
std::string graderSafeId(const std::string& id);  // "student-" + id when it is one, else id

// The escaping of safeEntryId without the bound: the whole name as safe text.
std::string escapedName(const std::string& name);

// "63 61 66 e9": the bytes of a name, for the record.
std::string hexBytes(const std::string& bytes);

}  // namespace rl
