// GLSL info logs of the drivers students meet, see driver_log.h for the
// formats. One regular expression per format keeps each readable on its own;
// logs are a few lines long, so std::regex's speed does not matter here.
#include "shader/driver_log.h"

#include <cctype>
#include <regex>

namespace rl {

namespace {

constexpr auto kFlags = std::regex::ECMAScript | std::regex::icase | std::regex::optimize;

// "0:12(5): error: msg", Mesa; also "preprocessor error:" from its glcpp.
const std::regex& mesaPattern() {
    static const std::regex re(R"(^\d+:(\d+)\((\d+)\):\s*(?:[a-z]+\s+)?(error|warning)\s*:\s*(.*)$)", kFlags);
    return re;
}

// "0(12) : error C1008: msg", NVIDIA; "(0) : error C2003: msg" in link logs.
// The code stays in the text: it is what NVIDIA's documentation is indexed by.
const std::regex& nvidiaPattern() {
    static const std::regex re(R"(^\d*\((\d+)\)\s*:\s*(?:[a-z]+\s+)?(error|warning)\s*:?\s*(.*)$)", kFlags);
    return re;
}

// "ERROR: 0:12: msg", glslang and the drivers built like it (AMD, Intel on
// Windows, Apple, ANGLE); some add a column, "ERROR: 0:12:5: msg".
const std::regex& glslangPattern() {
    static const std::regex re(R"(^(error|warning)\s*:\s*\d+:(\d+)(?::(\d+))?:\s*(.*)$)", kFlags);
    return re;
}

// "error: msg" without a location: Mesa's and NVIDIA's link errors,
// glslang's "ERROR: Linking fragment stage: ...".
const std::regex& barePattern() {
    static const std::regex re(R"(^(?:[a-z]+\s+)?(error|warning)\s*:\s*(.*)$)", kFlags);
    return re;
}

// Lines that only repeat or frame the messages.
const std::regex& noisePattern() {
    static const std::regex re(
        // glslang, AMD, Intel: "1 compilation errors.  No code generated."
        "compilation errors?\\.?\\s+no code generated"
        // NVIDIA's per-stage banner of link logs, and its underline
        "|^(vertex|fragment|geometry|compute|tess\\w*)( shader)? info$"
        "|^-+$"
        // AMD's banner before the errors, and its notes on success
        "|failed to compile with the following errors:?$"
        "|shader was successfully compiled"
        "|shader\\(s\\) linked"
        // several drivers on success
        "|^no errors\\.?$",
        kFlags);
    return re;
}

// Line and column numbers; absurd ones (more than 9 digits) count as unknown.
int number(const std::string& digits) {
    if (digits.empty() || digits.size() > 9) return 0;
    return std::stoi(digits);
}

std::string lowercase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The patterns only let "error" and "warning" through, in any case.
std::string severityOf(const std::string& word) { return lowercase(word) == "error" ? "error" : "warning"; }

std::string trim(const std::string& s) {
    const char* space = " \t\r\n\v\f";
    auto first = s.find_first_not_of(space);
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(space) - first + 1);
}

// One line of the log as a message, or false when it is not one.
bool parseMessage(const std::string& line, DriverMessage& out) {
    std::smatch m;
    if (std::regex_match(line, m, mesaPattern())) {
        out = {number(m[1]), number(m[2]), severityOf(m[3]), m[4]};
    } else if (std::regex_match(line, m, nvidiaPattern())) {
        out = {number(m[1]), 0, severityOf(m[2]), m[3]};
    } else if (std::regex_match(line, m, glslangPattern())) {
        out = {number(m[2]), number(m[3]), severityOf(m[1]), m[4]};
    } else if (std::regex_match(line, m, barePattern())) {
        out = {0, 0, severityOf(m[1]), m[2]};
    } else {
        return false;
    }
    return true;
}

}  // namespace

std::vector<DriverMessage> parseDriverLog(const std::string& log) {
    // glGetShaderInfoLog NUL-terminates inside the buffer it is given.
    std::string text = log.substr(0, log.find('\0'));
    std::vector<DriverMessage> messages;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = trim(text.substr(start, end - start));  // also drops the '\r' of "\r\n"
        start = end + 1;
        if (line.empty() || std::regex_search(line, noisePattern())) continue;

        DriverMessage message;
        if (parseMessage(line, message)) {
            messages.push_back(std::move(message));
        } else if (!messages.empty()) {
            messages.back().text += "\n" + line;  // a message that goes on over several lines
        } else {
            bool saysError = lowercase(line).find("error") != std::string::npos;
            messages.push_back({0, 0, saysError ? "error" : "warning", line});
        }
    }
    return messages;
}

}  // namespace rl
