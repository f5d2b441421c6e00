#include "shader/source_assembler.h"

#include "core/error.h"
#include "core/file_handle.h"
#include "core/legacy_text.h"
#include "core/paths.h"
#include "shader/loop_guard.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string_view>
#include <unordered_map>

namespace fs = std::filesystem;

namespace rl {

std::optional<SourceLocation> AssembledSource::locate(int combinedLine) const {
    if (combinedLine < 1 || combinedLine > int(lines.size())) return std::nullopt;
    return lines[std::size_t(combinedLine) - 1];
}

std::string AssembledSource::lineText(int combinedLine) const {
    if (combinedLine < 1 || combinedLine > int(lineStarts.size())) return {};
    std::size_t start = lineStarts[std::size_t(combinedLine) - 1];
    std::size_t end = text.find('\n', start);
    return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

std::string AssembledSource::authorLine(int combinedLine) const {
    std::optional<SourceLocation> where = locate(combinedLine);
    const SourceFile* file = where && !where->endOfFile ? source(where->file) : nullptr;
    if (!file || file->guarded.empty()) return lineText(combinedLine);
    std::size_t start = 0;
    for (int k = 1; k < where->line && start != std::string::npos; ++k) {
        start = file->text.find('\n', start);
        if (start != std::string::npos) ++start;
    }
    if (start == std::string::npos) return lineText(combinedLine);
    std::string line = file->text.substr(start, file->text.find('\n', start) - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

const SourceFile* AssembledSource::source(const std::string& shown) const {
    for (const SourceFile& f : sources)
        if (f.shown == shown) return &f;
    return nullptr;
}

void AssembledSource::append(const std::string& line, SourceLocation where) {
    lineStarts.push_back(text.size());
    text += line;
    text += '\n';
    lines.push_back(std::move(where));
}

std::string printable(const std::string& text, std::size_t limit) {
    std::string out;
    bool cut = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (out.size() >= limit) {
            cut = true;
            break;
        }
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += ' ';
        } else if (c < 0x20 || c == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        } else {
            out += char(c);
        }
    }
    if (cut) {
        // cut on a UTF-8 character boundary
        while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80) out.pop_back();
        if (!out.empty() && static_cast<unsigned char>(out.back()) >= 0xC0) out.pop_back();
        out += "...";
    }
    return out;
}

namespace {

// fs::weakly_canonical of the absolute path, remembered: assembling one
// program asks for the same folders and files many times over, and a grading
// child assembles dozens of programs (one complete submission made 33,000
// readlink and 16,000 stat calls, about a tenth of its CPU time, before).
// Bounded; a path's meaning does not change while raylab runs on it.
fs::path canonicalPath(const fs::path& path) {
    static std::mutex mutex;
    static std::unordered_map<std::string, fs::path> known;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = known.find(absolute.native()); it != known.end()) return it->second;
    fs::path resolved = fs::weakly_canonical(absolute, ec);
    if (known.size() >= 4096) known.clear();
    known.emplace(absolute.native(), resolved);
    return resolved;
}

}  // namespace

std::string displayPath(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = canonicalPath(path);
    for (const fs::path& base : {fs::current_path(ec), sourceRoot()}) {
        fs::path b = canonicalPath(base);
        auto rel = absolute.lexically_relative(b);
        if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    }
    return absolute.generic_string();
}

bool isInside(const fs::path& path, const fs::path& folder) {
    fs::path p = canonicalPath(path);
    fs::path f = canonicalPath(folder);
    auto rel = p.lexically_relative(f);
    return !rel.empty() && *rel.begin() != ".." && !rel.is_absolute();
}

namespace {

bool isValidUtf8(const std::string& s, std::size_t& badOffset) {
    std::size_t i = 0;
    while (i < s.size()) {
        unsigned char c = s[i];
        int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
        if (extra < 0 || i + extra >= s.size() + (extra == 0 ? 1 : 0)) { badOffset = i; return false; }
        for (int k = 1; k <= extra; ++k)
            if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) { badOffset = i; return false; }
        i += extra + 1;
    }
    return true;
}

}  // namespace

std::string readSourceFile(const fs::path& path) {
    const std::string shown = displayPath(path);
    // Opened without blocking (a FIFO would wait for a writer), then checked
    // on the open descriptor: only a regular file is read, and never more
    // than the limit (a device like /dev/zero has no end).
    InputFile file(path);
    if (!file.ok()) {
        const std::error_code& err = file.error();
        if (err == std::errc::no_such_file_or_directory || err == std::errc::not_a_directory)
            throw Error(shown + ": file not found");
        throw Error(shown + ": cannot be read: " + err.message());
    }
    if (file.type() == fs::file_type::directory) throw Error(shown + ": is a directory, expected a GLSL file");
    if (file.type() != fs::file_type::regular) throw Error(shown + ": is not a regular file, expected a GLSL file");
    // Sized from the file as opened, plus one byte to see a file that grew
    // past the limit: a buffer of the limit (256 KiB, zero-filled) for every
    // file of every assembly was 5% of a grading run's CPU in memset and
    // page faults (docs/grading.md, Scale).
    std::string text;
    text.resize(std::size_t(std::min<std::uintmax_t>(file.size(), kMaxShaderFileBytes)) + 1);
    std::size_t got = 0;
    for (;;) {
        if (got == text.size()) {
            if (text.size() > kMaxShaderFileBytes) break;
            text.resize(std::min<std::size_t>(text.size() * 2, kMaxShaderFileBytes + 1));
        }
        std::ptrdiff_t r = file.read(text.data() + got, text.size() - got);
        if (r < 0) throw Error(shown + ": cannot be read: " + file.error().message());
        if (r == 0) break;
        got += std::size_t(r);
    }
    if (got > kMaxShaderFileBytes)
        throw Error(shown + ": file is over the " + std::to_string(kMaxShaderFileBytes / 1024) +
                    " KiB limit for a shader file");
    text.resize(got);
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // a byte-order mark: editors on Windows write one
    std::size_t bad = 0;
    if (!isValidUtf8(text, bad)) {
        // One rule for check, grade, --ask and the browser page: bytes that are not UTF-8 inside
        // comments are read as Windows-1252 (core/legacy_text.h); outside a comment they are an error.
        LegacyTextResult legacy = commentsFromWindows1252(text);
        if (legacy.badLine != 0) {
            bad = legacy.badOffset;
            int line = 1 + int(std::count(text.begin(), text.begin() + long(bad), '\n'));
            throw Error(shown + ":" + std::to_string(line) + ": file is not UTF-8 text (byte " + std::to_string(bad) +
                        ")");
        }
        text = std::move(legacy.text);
    }
    if (auto nul = text.find('\0'); nul != std::string::npos) {
        int line = 1 + int(std::count(text.begin(), text.begin() + long(nul), '\n'));
        throw Error(shown + ":" + std::to_string(line) + ": file contains a NUL byte, not GLSL text");
    }
    return text;
}

namespace {

// A preprocessor directive: '#' first on the line (after white space), then
// its name. Returns false for any other line.
bool directive(std::string_view line, std::string_view& name, std::string_view& rest) {
    std::size_t k = line.find_first_not_of(" \t");
    if (k == std::string_view::npos || line[k] != '#') return false;
    k = line.find_first_not_of(" \t", k + 1);
    if (k == std::string_view::npos) {
        name = rest = {};
        return true;
    }
    std::size_t e = k;
    while (e < line.size() && (std::isalnum(static_cast<unsigned char>(line[e])) || line[e] == '_')) ++e;
    name = line.substr(k, e - k);
    rest = line.substr(e);
    return true;
}

// `"name"` or `<name>`, then nothing but white space or a // comment.
// Returns false when the directive does not have that shape.
bool includeName(std::string_view rest, std::string& name) {
    std::size_t k = rest.find_first_not_of(" \t");
    if (k == std::string_view::npos || (rest[k] != '"' && rest[k] != '<')) return false;
    char close = rest[k] == '"' ? '"' : '>';
    std::size_t e = rest.find(close, k + 1);
    if (e == std::string_view::npos) return false;
    name = std::string(rest.substr(k + 1, e - k - 1));
    std::size_t after = rest.find_first_not_of(" \t", e + 1);
    return after == std::string_view::npos || rest.substr(after, 2) == "//";
}

// Moves the block-comment state over one line; `opened` gets the line of a
// comment that starts here.
void followComments(std::string_view line, bool& inComment, int lineNumber, int& opened) {
    std::size_t k = 0;
    while (k < line.size()) {
        if (inComment) {
            std::size_t e = line.find("*/", k);
            if (e == std::string_view::npos) return;
            inComment = false;
            k = e + 2;
        } else {
            std::size_t slash = line.find('/', k);
            if (slash == std::string_view::npos || slash + 1 >= line.size()) return;
            if (line[slash + 1] == '/') return;
            if (line[slash + 1] == '*') {
                inComment = true;
                opened = lineNumber;
                k = slash + 2;
            } else {
                k = slash + 1;
            }
        }
    }
}

struct Frame {
    int source = 0;          // index in AssembledSource::sources
    std::size_t pos = 0;     // next byte to read
    int line = 0;            // lines read so far
    bool inComment = false;  // inside /* */ at the end of the last line
    int commentLine = 0;     // where that comment opened
    std::vector<int> conditionals;  // lines of the #if, #ifdef, #ifndef still open
};

}  // namespace

AssembledSource SourceAssembler::assemble(const std::string& prelude, const fs::path& root) const {
    AssembledSource out;
    {
        std::size_t pos = 0;
        for (int k = 1; pos < prelude.size(); ++k) {
            std::size_t end = prelude.find('\n', pos);
            if (end == std::string::npos) end = prelude.size();
            out.append(prelude.substr(pos, end - pos), {"<prelude>", k});
            pos = end + 1;
        }
    }
    std::vector<std::string> seen;
    std::vector<Frame> stack;
    // Reads `file` and starts it, unless it was included before.
    auto start = [&](const fs::path& file, const std::string& includedAs, int includer,
                     const std::string* generatedText = nullptr) {
        std::error_code ec;
        const std::string key = generatedText ? "<generated " + includedAs + ">" : canonicalPath(file).string();
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;  // included once
        seen.push_back(key);
        out.files.push_back(file);
        SourceFile source;
        source.path = file;
        source.shown = generatedText ? "<generated " + includedAs + ">" : displayPath(file);
        source.text = generatedText ? *generatedText : readSourceFile(file);
        source.includedAs = includedAs;
        source.exercise = !generatedText && isFramework_ && !isFramework_(file);
        if (source.exercise) {
            // Every loop bounded, the same on every machine (shader/loop_guard.h).
            GuardedSource guarded = guardLoops(source.text, source.shown, int(out.loops.size()) + 1);
            for (int line : guarded.loopLines) out.loops.push_back({source.shown, line});
            source.guarded = std::move(guarded.text);
            bool fromFramework = includer < 0 || !out.sources[std::size_t(includer)].exercise;
            source.owner = fromFramework ? int(out.sources.size()) : out.sources[std::size_t(includer)].owner;
        }
        out.sources.push_back(std::move(source));
        Frame frame;
        frame.source = int(out.sources.size()) - 1;
        stack.push_back(std::move(frame));
    };
    start(root, "", -1);
    int endMarkers = 0;
    while (!stack.empty()) {
        Frame& f = stack.back();
        const SourceFile& src = out.sources[std::size_t(f.source)];
        const std::string& shown = src.shown;
        const std::string& code = src.guarded.empty() ? src.text : src.guarded;
        if (f.pos >= code.size()) {
            if (src.exercise) {
                if (f.inComment)
                    throw Error(shown + ":" + std::to_string(f.commentLine) +
                                ": error: this comment is not closed by the end of the file (a '*/' is missing)");
                if (!f.conditionals.empty())
                    throw Error(shown + ":" + std::to_string(f.conditionals.back()) +
                                ": error: this #if has no #endif before the end of the file");
                if (src.owner == f.source) {
                    // Close the file's scope: harmless after a complete file, a syntax
                    // error inside a body, a declaration or parentheses left open.
                    out.append("void rl_endOfFile" + std::to_string(++endMarkers) + "() {}",
                               {shown, std::max(f.line, 1), true});
                }
            }
            stack.pop_back();
            continue;
        }
        std::size_t end = code.find('\n', f.pos);
        if (end == std::string::npos) end = code.size();
        std::string line = code.substr(f.pos, end - f.pos);
        f.pos = end + 1;
        const int k = ++f.line;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const bool startsInComment = f.inComment;
        followComments(line, f.inComment, k, f.commentLine);
        std::string_view name, rest;
        if (startsInComment || !directive(line, name, rest)) {
            out.append(line, {shown, k});
            continue;
        }
        const std::string where = shown + ":" + std::to_string(k) + ": ";
        if (name == "include") {
            std::string included;
            if (!includeName(rest, included))
                throw Error(where + "#include needs one file name in quotes: #include \"file.glsl\"");
            if (included.size() > kMaxIncludeName)
                throw Error(where + "#include name is " + std::to_string(included.size()) +
                            " characters long, over the limit of " + std::to_string(kMaxIncludeName));
            const std::string quoted = "#include \"" + printable(included) + "\"";
            if (stack.size() >= std::size_t(kMaxIncludeDepth))
                throw Error(where + quoted + ": includes nested more than " + std::to_string(kMaxIncludeDepth) +
                            " deep");
            if (auto gen = generated_.find(included); gen != generated_.end() && !src.exercise) {
                out.append("", {shown, k});
                const int includer = f.source;
                start(src.path.parent_path() / included, included, includer, &gen->second);
                continue;
            }
            fs::path target;
            try {
                target = resolver_(included, src.path);
            } catch (const Error& e) {
                throw Error(where + quoted + ": " + e.what());
            }
            std::error_code ec;
            const fs::file_status status = fs::status(target, ec);
            if (!fs::exists(status)) throw Error(where + quoted + ": " + displayPath(target) + ": file not found");
            if (!fs::is_regular_file(status))  // a FIFO would block, a device never end
                throw Error(where + quoted + ": " + displayPath(target) + ": is not a regular file");
            // Keep a blank line in place of the directive so line k stays line k.
            out.append("", {shown, k});
            const int includer = f.source;  // `f` and `src` are not valid after start()
            start(target, included, includer);
            continue;
        }
        if (name == "version") throw Error(where + "#version is set by raylab (330 core); remove this line");
        if (src.exercise) {
            if (name == "line")
                throw Error(where + "error: #line is not allowed in exercise files: raylab maps every error to "
                                    "your file and line itself; remove this line");
            if (name == "if" || name == "ifdef" || name == "ifndef") f.conditionals.push_back(k);
            if (name == "endif") {
                if (f.conditionals.empty())
                    throw Error(where + "error: #endif without an #if in this file");
                f.conditionals.pop_back();
            }
        }
        out.append(line, {shown, k});
    }
    return out;
}

}  // namespace rl
