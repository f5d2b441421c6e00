// Expands `#include "file"` in GLSL, which drivers do not do, and keeps a
// table from each line of the combined source back to the file and line the
// author wrote (Mesa does not accept file names in #line, so the host maps
// driver messages back itself).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rl {

struct SourceLocation {
    std::string file;  // as shown to the user, e.g. "exercises/05-ggx.glsl"
    int line = 0;      // 1-based
    // The line raylab adds after each exercise file to close its scope
    // (`void rl_endOfFileN() {}`): the driver stops there when the file
    // ends inside a body, a declaration or a parenthesis. `line` is the file's last line.
    bool endOfFile = false;
};

// One file of an assembly, as read (a UTF-8 byte-order mark removed).
struct SourceFile {
    std::filesystem::path path;
    std::string shown;       // displayPath(path)
    std::string text;
    std::string includedAs;  // the name in the #include that brought it in ("exercise/05-ggx.glsl")
    // An exercise file: not one of the framework's (a student's or the
    // solutions'), included by the framework or by another exercise file.
    bool exercise = false;
    // For exercise files: the index of the file the framework included, whose
    // scope this one belongs to (itself for those); -1 for framework files.
    int owner = -1;
    // What the driver gets of an exercise file: `text` with every loop
    // guarded (shader/loop_guard.h), line for line; empty for framework files.
    std::string guarded;
};

struct AssembledSource {
    std::string text;                  // what the driver compiles
    std::vector<SourceLocation> lines; // lines[k] is the origin of line k+1 of text
    std::vector<std::size_t> lineStarts;  // byte offset of line k+1 in text
    std::vector<std::filesystem::path> files;  // every file read, for hot reload
    std::vector<SourceFile> sources;   // every file read, with its text
    // The guarded loops of the exercise files (shader/loop_guard.h): loops[ID - 1]
    // is where loop ID starts in the file the author wrote.
    std::vector<SourceLocation> loops;

    // The origin of a 1-based line of `text`; nullopt when out of range.
    std::optional<SourceLocation> locate(int combinedLine) const;
    // The text of a 1-based line of `text`, without its newline.
    std::string lineText(int combinedLine) const;
    // That line as its author wrote it (before the loop guard); lineText for
    // lines raylab added.
    std::string authorLine(int combinedLine) const;
    // The source file shown as `shown`, or nullptr.
    const SourceFile* source(const std::string& shown) const;
    void append(const std::string& line, SourceLocation where);
};

// Where an include may come from. `resolve` gets the include name and the
// directory of the including file and returns the file to read, or throws
// rl::Error with the reason (not found, outside the allowed folder, ...).
using IncludeResolver =
    std::function<std::filesystem::path(const std::string& name, const std::filesystem::path& fromFile)>;
// Whether a file belongs to the framework (its errors are raylab's own).
using FrameworkTest = std::function<bool(const std::filesystem::path& file)>;
// Framework files the host writes itself (shader/readiness.h): include name
// -> text. A framework file's #include of such a name gets the text, shown
// as "<generated NAME>"; exercise files cannot include them.
using GeneratedFiles = std::map<std::string, std::string>;

// Limits on any single source file: bigger or non-UTF-8 files are refused
// with a message naming the file (students' files reach the driver through here).
constexpr std::size_t kMaxShaderFileBytes = 256 * 1024;
// Longest include name accepted (a file name, not a path through the disk).
constexpr std::size_t kMaxIncludeName = 255;
// Deepest chain of includes (the framework's is 3 deep).
constexpr int kMaxIncludeDepth = 16;

class SourceAssembler {
public:
    // Without `isFramework`, every file counts as the framework's.
    explicit SourceAssembler(IncludeResolver resolver, FrameworkTest isFramework = {}, GeneratedFiles generated = {})
        : resolver_(std::move(resolver)), isFramework_(std::move(isFramework)), generated_(std::move(generated)) {}

    // `prelude` comes first (the #version line and #defines), mapped to
    // "<prelude>". Each file is included at most once (like #pragma once).
    // Throws rl::Error "file:line: ..." for a bad include, a #version line,
    // and, in exercise files, a #line, an #if without #endif or a comment
    // not closed by the end of the file. Includes are expanded with an
    // explicit stack, never recursion.
    AssembledSource assemble(const std::string& prelude, const std::filesystem::path& root) const;

private:
    IncludeResolver resolver_;
    FrameworkTest isFramework_;
    GeneratedFiles generated_;
};

// A name or text from a file, fit for a one-line message: control
// characters escaped (\n, \x1b) and cut to `limit` bytes with "...".
std::string printable(const std::string& text, std::size_t limit = 80);

// How a path is shown in messages: relative to the working directory when
// inside it, else relative to the raylab root when inside that, else absolute.
std::string displayPath(const std::filesystem::path& path);

// Reads a whole text file, at most kMaxShaderFileBytes + 1 bytes of it, and
// drops a UTF-8 byte-order mark; throws rl::Error naming the file when it is
// missing, not a regular file (a directory, FIFO, device), unreadable, over
// kMaxShaderFileBytes, not UTF-8 or contains NUL bytes.
std::string readSourceFile(const std::filesystem::path& path);

// True when `path` (after resolving symlinks) lies inside `folder`.
bool isInside(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace rl
