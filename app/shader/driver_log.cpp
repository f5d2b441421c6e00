// GLSL info logs of the drivers students meet, see driver_log.h for the
// formats. Each format is read by a small hand-written matcher over one
// line: linear in the line's length and without recursion, because a log
// quotes the student's source (a 200,000-character identifier comes back in
// it, and std::regex recursed once per character on such lines).
#include "shader/driver_log.h"

#include <cctype>
#include <string_view>

namespace rl {

namespace {

// Longest message text kept from one log line; the rest is cut (messages
// quote the source, whose lines may be as long as a file).
constexpr std::size_t kMaxMessageText = 2000;
// Candidates kept in a "no matching function ... candidates are:" message.
constexpr int kMaxCandidates = 4;

bool equalsNoCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

// A position in one line and the few steps the formats are made of.
struct Cursor {
    std::string_view s;
    std::size_t i = 0;

    bool done() const { return i >= s.size(); }
    bool isSpace() const { return !done() && (s[i] == ' ' || s[i] == '\t'); }
    void spaces() {
        while (isSpace()) ++i;
    }
    bool literal(char c) {
        if (done() || s[i] != c) return false;
        ++i;
        return true;
    }
    // One or more digits; "" when none.
    std::string_view digits() {
        std::size_t start = i;
        while (!done() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
        return s.substr(start, i - start);
    }
    bool word(std::string_view w) {
        if (s.size() - i < w.size() || !equalsNoCase(s.substr(i, w.size()), w)) return false;
        i += w.size();
        return true;
    }
    std::string_view rest() const { return done() ? std::string_view() : s.substr(i); }
};

// "[word ]error|warning" followed by optional spaces and a colon (required
// unless colonOptional). Sets severity; false, with the cursor unmoved, otherwise.
bool severityWord(Cursor& c, std::string& severity, bool colonOptional) {
    const std::size_t start = c.i;
    auto tryHere = [&]() {
        std::size_t at = c.i;
        if (c.word("error")) severity = "error";
        else if (c.word("warning")) severity = "warning";
        else return false;
        Cursor probe = c;
        probe.spaces();
        if (probe.literal(':')) {
            c = probe;
            return true;
        }
        if (colonOptional && (c.done() || c.isSpace())) return true;
        c.i = at;
        return false;
    };
    if (tryHere()) return true;
    // One leading word ("preprocessor error:", "fatal error C9999:").
    while (!c.done() && std::isalpha(static_cast<unsigned char>(c.s[c.i]))) ++c.i;
    if (c.i > start && c.isSpace()) {
        c.spaces();
        if (tryHere()) return true;
    }
    c.i = start;
    return false;
}

// Line and column numbers; absurd ones (more than 9 digits) count as unknown.
int number(std::string_view digits) {
    if (digits.empty() || digits.size() > 9) return 0;
    return std::stoi(std::string(digits));
}

std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool endsWith(std::string_view s, std::string_view tail) {
    return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// Lines that only repeat or frame the messages.
bool isNoise(std::string_view line) {
    const std::string l = lowercase(line);
    // glslang, AMD, Intel: "1 compilation errors.  No code generated."
    for (std::size_t p = l.find("compilation error"); p != std::string::npos; p = l.find("compilation error", p + 1)) {
        std::size_t q = p + 17;
        if (q < l.size() && l[q] == 's') ++q;
        if (q < l.size() && l[q] == '.') ++q;
        std::size_t r = l.find_first_not_of(" \t", q);
        if (r != q && r != std::string::npos && l.compare(r, 17, "no code generated") == 0) return true;
    }
    // NVIDIA's per-stage banner of link logs, and its underline
    for (const char* stage : {"vertex", "fragment", "geometry", "compute", "tess"}) {
        std::string_view v(l);
        if (v.substr(0, std::char_traits<char>::length(stage)) != stage) continue;
        std::size_t e = std::char_traits<char>::length(stage);
        if (std::string_view(stage) == "tess")
            while (e < v.size() && (std::isalnum(static_cast<unsigned char>(v[e])) || v[e] == '_')) ++e;
        std::string_view tail = v.substr(e);
        if (tail == " info" || tail == " shader info") return true;
    }
    if (l.find_first_not_of('-') == std::string::npos) return true;
    // AMD's banner before the errors, and its notes on success
    if (endsWith(l, "failed to compile with the following errors") ||
        endsWith(l, "failed to compile with the following errors:"))
        return true;
    if (l.find("shader was successfully compiled") != std::string::npos) return true;
    if (l.find("shader(s) linked") != std::string::npos) return true;
    // several drivers on success
    return l == "no errors" || l == "no errors.";
}

std::string trim(std::string_view s) {
    const char* space = " \t\r\n\v\f";
    auto first = s.find_first_not_of(space);
    if (first == std::string_view::npos) return "";
    return std::string(s.substr(first, s.find_last_not_of(space) - first + 1));
}

// One line of the log as a message, or false when it is not one. `indented`
// tells that the text started with more white space than the one after the
// colon (Mesa's lines that go on the message before them).
bool parseMessage(std::string_view line, DriverMessage& out, bool& indented) {
    auto text = [&](Cursor c) {
        std::string_view rest = c.rest();
        std::size_t lead = rest.find_first_not_of(" \t");
        indented = lead != std::string_view::npos && lead >= 2;
        return trim(rest.substr(0, kMaxMessageText));
    };
    // Mesa: "0:12(5): error: msg", also "0:12(5): preprocessor error: msg"
    {
        Cursor c{line};
        if (!c.digits().empty() && c.literal(':')) {
            auto row = c.digits();
            if (!row.empty() && c.literal('(')) {
                auto col = c.digits();
                if (!col.empty() && c.literal(')') && c.literal(':')) {
                    c.spaces();
                    std::string severity;
                    if (severityWord(c, severity, false)) {
                        out = {number(row), number(col), severity, text(c)};
                        return true;
                    }
                }
            }
        }
    }
    // NVIDIA: "0(12) : error C1008: msg"; "(0) : error C2003: msg" in link logs.
    // The code stays in the text: it is what NVIDIA's documentation is indexed by.
    {
        Cursor c{line};
        c.digits();
        if (c.literal('(')) {
            auto row = c.digits();
            if (!row.empty() && c.literal(')')) {
                c.spaces();
                if (c.literal(':')) {
                    c.spaces();
                    std::string severity;
                    if (severityWord(c, severity, true)) {
                        c.spaces();
                        out = {number(row), 0, severity, text(c)};
                        return true;
                    }
                }
            }
        }
    }
    // glslang and the drivers built like it: "ERROR: 0:12: msg", "ERROR: 0:12:5: msg"
    {
        Cursor c{line};
        std::string severity;
        if (c.word("error")) severity = "error";
        else if (c.word("warning")) severity = "warning";
        if (!severity.empty()) {
            c.spaces();
            if (c.literal(':')) {
                c.spaces();
                if (!c.digits().empty() && c.literal(':')) {
                    auto row = c.digits();
                    if (!row.empty() && c.literal(':')) {
                        Cursor withColumn = c;
                        auto col = withColumn.digits();
                        int column = 0;
                        if (!col.empty() && withColumn.literal(':')) {
                            c = withColumn;
                            column = number(col);
                        }
                        out = {number(row), column, severity, text(c)};
                        return true;
                    }
                }
            }
        }
    }
    // "error: msg" without a location: Mesa's and NVIDIA's link errors,
    // glslang's "ERROR: Linking fragment stage: ...".
    {
        Cursor c{line};
        std::string severity;
        if (severityWord(c, severity, false)) {
            out = {0, 0, severity, text(c)};
            return true;
        }
    }
    return false;
}

}  // namespace

std::vector<DriverMessage> parseDriverLog(const std::string& log) {
    // glGetShaderInfoLog NUL-terminates inside the buffer it is given.
    std::string_view text(log.data(), std::min(log.size(), log.find('\0')));
    std::vector<DriverMessage> messages;
    int candidates = 0;  // lines already folded into the last message
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string line = trim(text.substr(start, end - start));  // also drops the '\r' of "\r\n"
        start = end + 1;
        if (line.empty() || isNoise(line)) continue;

        DriverMessage message;
        bool indented = false;
        if (parseMessage(line, message, indented)) {
            // Mesa repeats the location for each candidate of "no matching
            // function ... candidates are:", indented: one message, not 26.
            DriverMessage* last = messages.empty() ? nullptr : &messages.back();
            if (indented && last && last->line == message.line && last->column == message.column &&
                last->severity == message.severity) {
                ++candidates;
                if (candidates <= kMaxCandidates) last->text += (candidates == 1 ? " " : "; ") + message.text;
                continue;
            }
            if (candidates > kMaxCandidates && last)
                last->text += "; and " + std::to_string(candidates - kMaxCandidates) + " more";
            candidates = 0;
            messages.push_back(std::move(message));
        } else if (!messages.empty()) {
            messages.back().text += "\n" + line.substr(0, kMaxMessageText);  // a message that goes on over several lines
        } else {
            bool saysError = lowercase(line).find("error") != std::string::npos;
            messages.push_back({0, 0, saysError ? "error" : "warning", line.substr(0, kMaxMessageText)});
        }
    }
    if (candidates > kMaxCandidates && !messages.empty())
        messages.back().text += "; and " + std::to_string(candidates - kMaxCandidates) + " more";
    const std::string prefix = kUnfinishedPrefix;
    for (DriverMessage& m : messages)
        for (std::size_t at = m.text.find(prefix); at != std::string::npos; at = m.text.find(prefix, at))
            m.text.erase(at, prefix.size());
    return messages;
}

}  // namespace rl
