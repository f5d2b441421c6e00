#include "core/legacy_text.h"

namespace rl {

namespace {

// Length of the valid UTF-8 character at s[i] (1 for ASCII), or 0.
std::size_t utf8At(const std::string& s, std::size_t i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) return 1;
    const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    unsigned long cp = c & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
    for (std::size_t k = 1; k < n; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if ((d & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (d & 0x3F);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

// Windows-1252's 0x80..0x9F (0 where it defines no character); 0xA0..0xFF are Latin-1.
const unsigned short kHigh[32] = {0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,
                                  0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0,      0x017D, 0,
                                  0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
                                  0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

void appendUtf8(std::string& out, unsigned cp) {
    if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

}  // namespace

LegacyTextResult commentsFromWindows1252(const std::string& text) {
    LegacyTextResult r;
    r.text.reserve(text.size() + 16);
    enum class State { Code, Line, Block } state = State::Code;
    int line = 1;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (state == State::Code && c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
            state = text[i + 1] == '/' ? State::Line : State::Block;
            r.text.append(text, i, 2);
            i += 2;
            continue;
        }
        if (state == State::Block && c == '*' && i + 1 < text.size() && text[i + 1] == '/') {
            state = State::Code;
            r.text.append("*/");
            i += 2;
            continue;
        }
        if (c == '\n') {
            ++line;
            if (state == State::Line) state = State::Code;
        }
        const std::size_t n = utf8At(text, i);
        if (n > 0) {
            r.text.append(text, i, n);
            i += n;
            continue;
        }
        const unsigned char b = static_cast<unsigned char>(c);
        if (state == State::Code) {
            if (r.badLine == 0) {
                r.badLine = line;
                r.badOffset = i;
                r.badByte = b;
            }
            r.text += c;
        } else {
            const unsigned cp = b >= 0xA0 ? b : kHigh[b - 0x80] ? kHigh[b - 0x80] : 0xFFFD;
            appendUtf8(r.text, cp);
            if (r.converted++ == 0) r.firstConvertedLine = line;
        }
        ++i;
    }
    return r;
}

}  // namespace rl
