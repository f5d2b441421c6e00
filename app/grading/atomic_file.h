// The grader's files: what a reader (a second run, `raylab grade merge`, an
// instructor's browser) sees either whole or not at all, through the one
// atomic writer of core/file_io.h, so an interrupted run never leaves half a
// grade behind.
#pragma once

#include "core/file_handle.h"
#include "core/file_io.h"

#include <filesystem>
#include <string>

namespace rl {

// Writes `content` to `path` atomically, creating the parent folders.
// Throws rl::Error "path: cannot write (reason)".
inline void writeOutputFile(const std::filesystem::path& path, const std::string& content) {
    writeFileAtomic(path, content, WriteOptions{"", true});
}

// Reads a whole regular file of at most 16 MiB; throws rl::Error "path: cannot read (reason)".
inline std::string readWholeFile(const std::filesystem::path& path) {
    return readRegularFile(path, kMaxTextFileBytes);
}

// Holds an exclusive lock on FOLDER/.lock while it lives, so that two runs
// never write one output folder at once (the second one stops with
// rl::Error "FOLDER: another raylab grade is writing here"). Forked workers
// share it; it goes with the process, however that ends.
class FolderLock {
public:
    explicit FolderLock(const std::filesystem::path& folder);
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    FileLock lock_;
};

// Whether either path is the other or lies inside it (after resolving links).
bool pathsOverlap(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace rl
