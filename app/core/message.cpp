// Escaping and cutting of outside text in messages (see message.h).
#include "core/message.h"

#include <cstdint>
#include <cstdio>

namespace rl {

bool isBidiControl(std::uint32_t cp);

namespace {

// Length of the valid UTF-8 sequence at s[i], or 0 when it is not one
// (overlong forms, surrogates and values past U+10FFFF are not).
std::size_t utf8Length(std::string_view s, std::size_t i, std::uint32_t& codePoint) {
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    unsigned char b = byte(i);
    std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    codePoint = n == 1 ? b : n == 2 ? (b & 0x1F) : n == 3 ? (b & 0x0F) : (b & 0x07);
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        codePoint = (codePoint << 6) | (byte(i + k) & 0x3F);
    }
    static const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (codePoint < smallest[n] || codePoint > 0x10FFFF || (codePoint >= 0xD800 && codePoint <= 0xDFFF)) return 0;
    return n;
}

std::string hexEscape(unsigned value) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "\\x%02x", value & 0xFF);
    return buffer;
}

// Escapes control characters (C0, DEL and the C1 range U+0080..U+009F, which
// some terminals obey too) and invalid bytes; keeps newlines when asked.
std::string escape(std::string_view text, std::size_t maxChars, bool keepNewlines, bool* cut = nullptr) {
    std::string out;
    std::size_t chars = 0, i = 0;
    for (; i < text.size() && chars < maxChars; ++chars) {
        std::uint32_t cp = 0;
        std::size_t n = utf8Length(text, i, cp);
        if (n == 0) {
            out += hexEscape(static_cast<unsigned char>(text[i]));
            ++i;
            continue;
        }
        if (cp == '\n' && keepNewlines) out += '\n';
        else if (cp == '\n') out += "\\n";
        else if (cp == '\t') out += "\\t";
        else if (cp == '\r') out += "\\r";
        else if (cp < 0x20 || cp == 0x7F) out += hexEscape(cp);
        else if (cp >= 0x80 && cp <= 0x9F) out += "\\u00" + hexEscape(cp).substr(2);
        else if (isBidiControl(cp)) {
            char u[12];
            std::snprintf(u, sizeof u, "\\u%04x", unsigned(cp));
            out += u;
        }
        else out.append(text.substr(i, n));
        i += n;
    }
    if (cut) *cut = i < text.size();
    else if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

}  // namespace

bool isBidiControl(std::uint32_t cp) {
    return cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
           (cp >= 0x2066 && cp <= 0x2069);
}

std::string printable(std::string_view text, std::size_t maxChars) { return escape(text, maxChars, false); }

std::string printableLines(std::string_view text, std::size_t maxChars) { return escape(text, maxChars, true); }

std::string quotedValue(std::string_view text, std::size_t maxChars) {
    bool cut = false;
    std::string body = escape(text, maxChars, false, &cut);
    if (cut) return "'" + body + "...' (" + std::to_string(text.size()) + " bytes)";
    return "'" + body + "'";
}

std::string oneLine(std::string_view message, std::size_t maxChars) { return escape(message, maxChars, false); }

}  // namespace rl
