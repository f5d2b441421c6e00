#include "walkthrough/doc_commands.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace rl::walkthrough {

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::size_t indentation(const std::string& line) {
    std::size_t n = line.find_first_not_of(' ');
    return n == std::string::npos ? line.size() : n;
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

std::string trim(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

bool isCommandLine(const std::string& line) {
    return startsWith(line, "./raylab ") || line == "./raylab" || startsWith(line, "scripts/") ||
           startsWith(line, "cmake ");
}

// One space for every run of white space, no leading/trailing space, and any
// duration "(3 s)" or "(0.4 s)" written "(N s)".
std::string normalised(const std::string& line) {
    static const std::regex space("\\s+"), duration("\\([0-9.]+ s\\)");
    return trim(std::regex_replace(std::regex_replace(line, duration, "(N s)"), space, " "));
}

}  // namespace

std::vector<CodeBlock> codeBlocks(const std::string& markdown) {
    std::vector<std::string> lines = splitLines(markdown);
    std::vector<CodeBlock> blocks;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string t = trim(lines[i]);
        if (startsWith(t, "```") || startsWith(t, "~~~")) {
            std::string fence = t.substr(0, 3);
            std::size_t indent = indentation(lines[i]);
            CodeBlock b;
            b.line = int(i) + 2;
            for (++i; i < lines.size() && !startsWith(trim(lines[i]), fence); ++i)
                b.lines.push_back(lines[i].substr(std::min(indent, indentation(lines[i]))));
            blocks.push_back(b);
            continue;
        }
        bool afterBlank = i == 0 || blank(lines[i - 1]);
        if (!afterBlank || blank(lines[i]) || indentation(lines[i]) < 4 || startsWith(t, "|")) continue;
        CodeBlock b;
        b.line = int(i) + 1;
        std::size_t start = i;
        while (i < lines.size() && (blank(lines[i]) || indentation(lines[i]) >= 4)) ++i;
        while (i > start && blank(lines[i - 1])) --i;
        std::size_t indent = std::string::npos;
        for (std::size_t k = start; k < i; ++k)
            if (!blank(lines[k])) indent = std::min(indent, indentation(lines[k]));
        for (std::size_t k = start; k < i; ++k) b.lines.push_back(blank(lines[k]) ? "" : lines[k].substr(indent));
        blocks.push_back(b);
        --i;
    }
    return blocks;
}

std::vector<DocCommand> commands(const std::string& markdown) {
    std::vector<DocCommand> out;
    auto add = [&](int line, const std::string& text) {
        for (const DocCommand& c : out)
            if (c.text == text) return;
        out.push_back({line, text});
    };
    // Commands in code blocks and in inline spans, merged in document order.
    std::vector<std::pair<int, std::string>> found;
    std::vector<CodeBlock> blocks = codeBlocks(markdown);
    std::vector<bool> inBlock(splitLines(markdown).size() + 2, false);
    for (const CodeBlock& b : blocks) {
        for (std::size_t k = 0; k < b.lines.size(); ++k) {
            inBlock[b.line + k] = true;
            if (isCommandLine(trim(b.lines[k]))) found.emplace_back(b.line + int(k), trim(b.lines[k]));
        }
    }
    static const std::regex span("`(\\./raylab [^`]*)`");
    std::vector<std::string> lines = splitLines(markdown);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (inBlock[i + 1]) continue;
        for (std::sregex_iterator m(lines[i].begin(), lines[i].end(), span), end; m != end; ++m)
            found.emplace_back(int(i) + 1, (*m)[1].str());
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [line, text] : found) add(line, text);
    return out;
}

std::vector<CodeBlock> checkerOutputs(const std::string& markdown) {
    static const std::regex verdict("^[0-9][0-9]-[a-z0-9-]+ +(PASS|FAIL|NOT STARTED|COMPILE ERROR|TIMEOUT|CRASH)( .*)?$");
    std::vector<CodeBlock> out;
    for (const CodeBlock& b : codeBlocks(markdown)) {
        if (b.lines.empty()) continue;
        std::string first = trim(b.lines.front());
        if (std::regex_match(first, verdict) || startsWith(first, "hint: ")) out.push_back(b);
    }
    return out;
}

std::string optionValue(const std::string& command, const std::string& name) {
    std::istringstream in(command);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    for (std::size_t k = 0; k + 1 < words.size(); ++k)
        if (words[k] == name) return words[k + 1];
    return "";
}

bool showsOutput(const std::vector<std::string>& shown, const std::string& output) {
    std::vector<std::string> got;
    for (const std::string& line : splitLines(output)) got.push_back(normalised(line));
    std::size_t at = 0;
    for (const std::string& raw : shown) {
        std::string want = normalised(raw);
        if (want.empty() || want == "...") continue;
        bool prefix = want.size() > 3 && want.compare(want.size() - 3, 3, "...") == 0;
        if (prefix) want = trim(want.substr(0, want.size() - 3));
        while (at < got.size() && !(prefix ? startsWith(got[at], want) : got[at] == want)) ++at;
        if (at == got.size()) return false;
        ++at;
    }
    return true;
}

}  // namespace rl::walkthrough
