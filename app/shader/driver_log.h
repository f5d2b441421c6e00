// Parses the info log a GLSL compiler or linker hands back, whatever the
// driver, into messages with a line number. Mapping that line back to the
// file the author wrote is program.cpp's job (through AssembledSource).
//
// Recognised formats (the number before the line is the source-string index,
// always 0 for raylab, which passes one string):
//   Mesa (all Linux drivers)   0:12(5): error: message
//                              0:12(5): preprocessor error: message
//   NVIDIA                     0(12) : error C1008: message      (code kept in text)
//   AMD, Intel (Windows),      ERROR: 0:12: message
//   Apple, ANGLE, glslang      WARNING: 0:12: message
//   no location (link errors)  error: message / ERROR: message   -> line 0
// Summaries and banners that repeat what the messages say ("ERROR: 1
// compilation errors.  No code generated.", NVIDIA's "Fragment info" and
// "-------------") are dropped. Any other line that is not a message is kept
// as the continuation of the message before it, or, with none before it, as
// a line-0 message of its own (severity "error" when it says "error",
// "warning" otherwise), so text from an unknown driver is never lost.
#pragma once

#include <string>
#include <vector>

namespace rl {

struct DriverMessage {
    int line = 0;          // 1-based line in the source string given to the driver; 0 when unknown
    int column = 0;        // 1-based as the driver reports it; 0 when unknown
    std::string severity;  // "error" or "warning"
    std::string text;      // message without location prefix
};

// Accepts "\n" or "\r\n" line ends, blank lines, and the trailing NUL that
// glGetShaderInfoLog writes into a buffer of GL_INFO_LOG_LENGTH bytes.
std::vector<DriverMessage> parseDriverLog(const std::string& log);

// The name the host gives an unfinished function's own definition while it
// compiles the neutral value in its place (shader/readiness.h). Driver
// messages quote the function by its author's name: parseDriverLog() drops
// the prefix.
inline constexpr const char* kUnfinishedPrefix = "rl_unfinished_";

}  // namespace rl
