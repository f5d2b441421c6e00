// Extracts a student's .zip without trusting it: nothing is ever written
// outside the destination folder, and an archive built to hurt the grader is
// refused as a whole (rl::Error with the reason; nothing is left in the
// destination) instead of half-extracted:
//   - entry names that are absolute, hold "..", backslashes, drive letters
//     or control characters (zip slip);
//   - more entries, more bytes in total, or a higher compression ratio than
//     the limits allow (zip bombs; sizes are counted while inflating, not
//     taken from the archive's own headers);
//   - a corrupt or encrypted archive.
// Symbolic-link entries are not extracted: they come back in `refused`, so
// that the grader can refuse the exercise they stand for, as it does for a
// symlink in a submitted folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace rl {

struct UnzipLimits {
    std::size_t maxListedEntries = 100000;                   // entries in the archive's directory, extracted or not
    std::size_t maxEntries = 2000;                           // entries extracted
    std::uint64_t maxTotalBytes = std::uint64_t(64) << 20;  // all entries, inflated
    std::uint64_t maxEntryBytes = std::uint64_t(16) << 20;
    double maxRatio = 200;                                   // inflated / compressed, per entry ...
    std::uint64_t ratioCheckAbove = std::uint64_t(1) << 20;  // ... for entries bigger than this (tiny files compress well)
};

struct UnzipResult {
    std::map<std::string, std::string> refused;  // entry path -> why it was not extracted
    std::size_t files = 0;                       // regular files extracted
    std::vector<std::string> skipped;            // files left in the archive: not wanted
};

// Which entries to extract ("exercises/05-ggx.glsl"); the others are not
// written and count against no size limit (a build folder in a repository's
// zip), but their names are checked all the same.
using UnzipFilter = std::function<bool(const std::string& path)>;

// `dest` must not exist yet or be empty. Throws rl::Error "NAME.zip: reason".
UnzipResult extractZipSafely(const std::filesystem::path& zip, const std::filesystem::path& dest,
                             const UnzipLimits& limits = {}, const UnzipFilter& wanted = {});

}  // namespace rl
