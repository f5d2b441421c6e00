// Files that a reader (a second run, `raylab grade merge`, an instructor's
// browser) sees either whole or not at all: written to a temporary file
// beside the target, flushed, then renamed over it, so an interrupted run
// never leaves half a grade behind.
#pragma once

#include <filesystem>
#include <string>

namespace rl {

// Writes `content` to `path` atomically, creating the parent folders.
// Throws rl::Error "path: cannot write (reason)".
void writeFileAtomic(const std::filesystem::path& path, const std::string& content);

// Reads a whole file; throws rl::Error "path: cannot read (reason)".
std::string readWholeFile(const std::filesystem::path& path);

}  // namespace rl
