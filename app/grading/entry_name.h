// The name of an entry of SUBMISSIONS as a safe id. A file system name is
// any bytes but '/' and NUL; an LMS writes UTF-8 (Canvas keeps Unicode
// letters, Moodle full names), a zip made on Windows may carry CP-1252 or
// CP-437 bytes, and a hostile name may carry terminal escapes. An id is
// written into JSON (which must be UTF-8), HTML, CSV and folder names in
// OUT, and shown on the terminal, so a name that is not plain UTF-8 text
// becomes an escaped id ("caf%E9") while its original bytes are kept
// (as hex) for the export and the instructor.
#pragma once

#include <string>

namespace rl {

// Valid UTF-8 (no overlong forms, no surrogates) without control
// characters (C0, DEL, C1): a name that can be written anywhere as it is.
bool isPlainUtf8(const std::string& name);

// The name itself when isPlainUtf8; otherwise every byte that is not part of
// plain UTF-8 text, and '%', as "%XX" (upper-case hex): stable, unique for
// distinct names, and valid UTF-8.
std::string safeEntryId(const std::string& name);

// "63 61 66 e9": the bytes of a name, for the record.
std::string hexBytes(const std::string& bytes);

}  // namespace rl
