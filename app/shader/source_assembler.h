// Expands `#include "file"` in GLSL, which drivers do not do, and keeps a
// table from each line of the combined source back to the file and line the
// author wrote (Mesa does not accept file names in #line, so the host maps
// driver messages back itself).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rl {

struct SourceLocation {
    std::string file;  // as shown to the user, e.g. "exercises/05-ggx.glsl"
    int line = 0;      // 1-based
};

struct AssembledSource {
    std::string text;                  // what the driver compiles
    std::vector<SourceLocation> lines; // lines[k] is the origin of line k+1 of text
    std::vector<std::filesystem::path> files;  // every file read, for hot reload

    // The origin of a 1-based line of `text`; nullopt when out of range.
    std::optional<SourceLocation> locate(int combinedLine) const;
    // The text of a 1-based line of `text`, without its newline.
    std::string lineText(int combinedLine) const;
};

// Where an include may come from. `resolve` gets the include name and the
// directory of the including file and returns the file to read, or throws
// rl::Error with the reason (not found, outside the allowed folder, ...).
using IncludeResolver =
    std::function<std::filesystem::path(const std::string& name, const std::filesystem::path& fromFile)>;

// Limits on any single source file: bigger or non-UTF-8 files are refused
// with a message naming the file (students' files reach the driver through here).
constexpr std::size_t kMaxShaderFileBytes = 256 * 1024;

class SourceAssembler {
public:
    explicit SourceAssembler(IncludeResolver resolver) : resolver_(std::move(resolver)) {}

    // `prelude` comes first (the #version line and #defines), mapped to
    // "<prelude>". Each file is included at most once (like #pragma once).
    // Throws rl::Error "file:line: ..." for a bad include.
    AssembledSource assemble(const std::string& prelude, const std::filesystem::path& root) const;

private:
    void appendFile(const std::filesystem::path& file, AssembledSource& out, std::vector<std::string>& seen) const;
    IncludeResolver resolver_;
};

// How a path is shown in messages: relative to the working directory when
// inside it, else relative to the raylab root when inside that, else absolute.
std::string displayPath(const std::filesystem::path& path);

// Reads a whole text file; throws rl::Error naming the file when it is
// missing, a directory, unreadable, over kMaxShaderFileBytes or not UTF-8.
std::string readSourceFile(const std::filesystem::path& path);

// True when `path` (after resolving symlinks) lies inside `folder`.
bool isInside(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace rl
