// Exercise files saved by an editor on Windows in its "ANSI" code page
// (Windows-1252): an "é" or a curly quote in a comment is one byte that is
// not UTF-8. Comments never reach the compiler, so such bytes there are read
// as Windows-1252 (converted to UTF-8 in the staged copy, with a note for the
// student) instead of costing the exercise; outside comments a byte that is
// not UTF-8 stays an error naming the file, line and byte.
#pragma once

#include <cstddef>
#include <string>

namespace rl {

struct LegacyTextResult {
    std::string text;           // the converted text (== input when nothing was converted)
    std::size_t converted = 0;  // bytes read as Windows-1252 inside comments
    int firstConvertedLine = 0;
    // The first byte that is not UTF-8 outside a comment (left as it is): 0 line when none.
    int badLine = 0;
    std::size_t badOffset = 0;
    unsigned char badByte = 0;
};

// Converts the bytes that are not UTF-8 inside // and /* */ comments from
// Windows-1252 (the five bytes it leaves undefined become U+FFFD).
LegacyTextResult commentsFromWindows1252(const std::string& text);

}  // namespace rl
