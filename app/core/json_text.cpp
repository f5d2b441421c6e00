// Parsing JSON text with positions in every message (see json_text.h).
#include "core/json_text.h"

#include "core/error.h"
#include "core/message.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace rl {

namespace {

bool isNumberChar(char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// The one linear pass before nlohmann's parser (see json_text.h).
void scanJsonText(const std::string& text, const std::string& origin) {
    std::size_t line = 1, lineStart = 0;
    auto fail = [&](std::size_t at, const std::string& what) {
        throw Error(origin + ":" + std::to_string(line) + ":" + std::to_string(at - lineStart + 1) + ": " + what);
    };
    int depth = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (c == '\0') {
            fail(i, "NUL byte (is this a binary file?)");
        } else if (c == '"') {  // a string: skip to its end; nlohmann judges what is inside
            for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {
                if (text[i] == '\0') fail(i, "NUL byte (is this a binary file?)");
                if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] != '\n') ++i;
            }
            if (i < text.size() && text[i] == '\n') --i;  // an unclosed string: the newline is counted above
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) fail(i, "values nest more than " + std::to_string(kMaxJsonDepth) + " deep");
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t end = i;
            while (end < text.size() && isNumberChar(text[end])) ++end;
            std::string token = text.substr(i, std::min<std::size_t>(end - i, 4096));
            errno = 0;
            double v = std::strtod(token.c_str(), nullptr);
            if (end - i > 4096 || (errno == ERANGE && std::isinf(v)))
                fail(i, "number " + quotedValue(text.substr(i, std::min<std::size_t>(end - i, 64)), 24) +
                            " is out of range (at most about 1.8e308)");
            i = end - 1;
        }
    }
}

// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error
// while parsing value - invalid literal; last read: 'tru'" becomes "syntax error: invalid
// literal; last read: 'tru'" (cut: the last read token can be the rest of the file).
std::string syntaxDetail(const std::string& what) {
    auto pos = what.find("syntax error while parsing value - ");
    std::string detail = pos == std::string::npos ? what : what.substr(pos + 35);
    if (pos == std::string::npos && (pos = what.find("syntax error")) != std::string::npos) detail = what.substr(pos);
    return printable(detail, 160);
}

std::string lineColumn(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace

nlohmann::json parseJsonText(const std::string& text, const std::string& origin) {
    scanJsonText(text, origin);
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is 1-based, pointing just past the offending character.
        std::string detail = syntaxDetail(e.what());
        if (detail.rfind("syntax error", 0) != 0) detail = "syntax error: " + detail;
        throw Error(origin + ":" + lineColumn(text, e.byte > 0 ? e.byte - 1 : 0) + ": " + detail);
    } catch (const nlohmann::json::exception& e) {  // anything the scan above missed: still one line
        throw Error(origin + ": not valid JSON (" + printable(e.what(), 160) + ")");
    }
}

std::string describeJsonValue(const nlohmann::json& v) {
    if (v.is_string()) return quotedValue(v.get_ref<const std::string&>());
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    if (v.is_object()) return "an object with " + std::to_string(v.size()) + (v.size() == 1 ? " key" : " keys");
    return v.dump();  // a number, true, false or null: short, not recursive
}

}  // namespace rl
