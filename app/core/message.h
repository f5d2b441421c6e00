// Text that reaches the terminal from outside raylab (a value or key from a
// scene file, an option's argument, a file name) is quoted through here:
// cut to a short prefix and with control characters escaped, so that every
// message stays one short line and no ANSI escape reaches the terminal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rl {

// Quoting for a value inside a message: 'abc', or 'abcdefgh...' (1048576 bytes)
// when longer than maxChars characters. Control characters become \n, \t,
// \x1b and so on, bidirectional controls \u202e; bytes that are not UTF-8 become \xNN.
std::string quotedValue(std::string_view text, std::size_t maxChars = 40);

// The bidirectional controls (U+061C, U+200E/F, U+202A..U+202E,
// U+2066..U+2069): a name holding one displays in another order than its
// bytes (U+202E turns "abc\u202Egnp.exe" into "abcexe.png"); escaped as
// \u202e with the control characters.
bool isBidiControl(std::uint32_t codePoint);

// The same escaping and cut without the quotes (for whole messages).
std::string printable(std::string_view text, std::size_t maxChars);

// The same, keeping newlines: for reports that are several lines by design
// (a shader compiler's errors, each followed by its source line).
std::string printableLines(std::string_view text, std::size_t maxChars);

// A whole message as one terminal line: newlines escaped too, at most
// maxChars characters (2000: a path, a field, a quoted value and a rule fit).
std::string oneLine(std::string_view message, std::size_t maxChars = 2000);

}  // namespace rl
