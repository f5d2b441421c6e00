// Every file raylab writes and every non-shader file it reads goes through
// here, so that "nothing lost, never hang" is decided in one place.
//
// Writing: the content goes to a temporary file in the target's folder, is
// flushed to the disk (fsync) and renamed over the target, so a reader (a
// second run, a browser, the file watcher) sees the old file or the new one,
// never half of one; on any failure the old content is intact and the
// temporary file is gone. A target that exists but is not a regular file (a
// device such as /dev/full, a FIFO, a folder) is refused: renaming over it
// would delete it, and writing into it is rarely what was meant. A symbolic
// link to a regular file is kept: its target is replaced.
//
// Reading: only regular files, opened without blocking (a FIFO named as a
// scene must not wait forever for a writer), and at most `maxBytes` (so
// /dev/zero or a runaway file cannot eat the memory).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rl {

struct WriteOptions {
    const char* what = "";        // "PNG", "the CSV": goes into "path: cannot write PNG (reason)"
    bool createFolders = false;   // create missing parent folders (the grader's output tree)
};

// Throws rl::Error "path: cannot write <what> (reason)".
void writeFileAtomic(const std::filesystem::path& path, std::string_view content, const WriteOptions& options = {});

// Refuses early, before minutes of rendering, an output path that exists and
// is not a regular file (the same refusal writeFileAtomic makes at the end).
void requireOutputPath(const std::filesystem::path& path, const char* what = "");

// Limits for files that are not images: scenes, rubrics, grade records, input scripts.
// 16 MiB: the largest legal scene (64 spheres, 16 lights) is under 20 KB; a grade
// record or rubric for a class of thousands is a few MB.
constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t(16) << 20;
// Images (PNG, PFM) up to 16384x16384 RGB float: 3.2 GB; 4 GiB bounds them.
constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t(4) << 30;

// Reads a whole regular file of at most maxBytes. Throws rl::Error
// "path: cannot read <what> (reason)", with the reasons "not found",
// "is a directory", "not a regular file (a FIFO)", "larger than 16 MiB".
std::string readRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* what = "");

// "16 MiB", "4 GiB", "512 bytes": for the limits in messages.
std::string byteSizeText(std::uintmax_t bytes);

// A new folder under the system's temporary folder that only this user can
// open (mkdtemp: "raylab-<what>-XXXXXX", mode 0700), removed with its files
// when the process that made it exits normally (a forked child that inherits
// it leaves it alone). Throws rl::Error naming the folder it could not make.
std::filesystem::path privateTempFolder(const std::string& what);

}  // namespace rl
