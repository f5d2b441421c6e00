#include "shader/source_assembler.h"

#include "core/error.h"
#include "core/paths.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace rl {

std::optional<SourceLocation> AssembledSource::locate(int combinedLine) const {
    if (combinedLine < 1 || combinedLine > int(lines.size())) return std::nullopt;
    return lines[combinedLine - 1];
}

std::string AssembledSource::lineText(int combinedLine) const {
    if (combinedLine < 1) return {};
    std::istringstream in(text);
    std::string line;
    for (int k = 1; std::getline(in, line); ++k)
        if (k == combinedLine) return line;
    return {};
}

std::string displayPath(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::weakly_canonical(fs::absolute(path, ec), ec);
    for (const fs::path& base : {fs::current_path(ec), sourceRoot()}) {
        fs::path b = fs::weakly_canonical(base, ec);
        auto rel = absolute.lexically_relative(b);
        if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    }
    return absolute.generic_string();
}

bool isInside(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    fs::path f = fs::weakly_canonical(folder, ec);
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
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(shown + ": file not found");
    if (fs::is_directory(path, ec)) throw Error(shown + ": is a directory, expected a GLSL file");
    auto size = fs::file_size(path, ec);
    if (!ec && size > kMaxShaderFileBytes)
        throw Error(shown + ": file is " + std::to_string(size / 1024) + " KiB, over the " +
                    std::to_string(kMaxShaderFileBytes / 1024) + " KiB limit for a shader file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(shown + ": cannot be read");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    std::size_t bad = 0;
    if (!isValidUtf8(text, bad)) {
        int line = 1 + int(std::count(text.begin(), text.begin() + bad, '\n'));
        throw Error(shown + ":" + std::to_string(line) + ": file is not UTF-8 text (byte " + std::to_string(bad) +
                    ")");
    }
    if (text.find('\0') != std::string::npos) throw Error(shown + ": file contains NUL bytes, not GLSL text");
    return text;
}

AssembledSource SourceAssembler::assemble(const std::string& prelude, const fs::path& root) const {
    AssembledSource out;
    std::istringstream in(prelude);
    std::string line;
    for (int k = 1; std::getline(in, line); ++k) {
        out.text += line + "\n";
        out.lines.push_back({"<prelude>", k});
    }
    std::vector<std::string> seen;
    appendFile(root, out, seen);
    return out;
}

void SourceAssembler::appendFile(const fs::path& file, AssembledSource& out,
                                 std::vector<std::string>& seen) const {
    std::error_code ec;
    const std::string key = fs::weakly_canonical(file, ec).string();
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;  // included once
    seen.push_back(key);
    out.files.push_back(file);

    const std::string shown = displayPath(file);
    const std::string text = readSourceFile(file);
    // #include "name" alone on its line; other directives pass through.
    static const std::regex includeLine(R"(^\s*#\s*include\s*(["<])([^">]*)[">]\s*(//.*)?$)");
    std::istringstream in(text);
    std::string line;
    for (int k = 1; std::getline(in, line); ++k) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch m;
        if (std::regex_match(line, m, includeLine)) {
            const std::string where = shown + ":" + std::to_string(k) + ": ";
            fs::path target;
            try {
                target = resolver_(m[2].str(), file);
            } catch (const Error& e) {
                throw Error(where + "#include \"" + m[2].str() + "\": " + e.what());
            }
            std::error_code missing;
            if (!fs::is_regular_file(target, missing))
                throw Error(where + "#include \"" + m[2].str() + "\": " + displayPath(target) + ": file not found");
            // Keep a blank line in place of the directive so line k stays line k.
            out.text += "\n";
            out.lines.push_back({shown, k});
            appendFile(target, out, seen);
            continue;
        }
        static const std::regex versionLine(R"(^\s*#\s*version\b)");
        if (std::regex_search(line, versionLine))
            throw Error(shown + ":" + std::to_string(k) +
                        ": #version is set by raylab (330 core); remove this line");
        out.text += line + "\n";
        out.lines.push_back({shown, k});
    }
}

}  // namespace rl
