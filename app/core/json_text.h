// JSON read from files (scenes, rubrics, grade records): parsed with
// nlohmann-json after one linear pass that refuses what that library lets
// through or reports badly, each as one line "origin:line:column: ...":
// a NUL byte (nlohmann stops reading there and accepts the rest unseen),
// nesting deeper than kMaxJsonDepth (a value 100,000 arrays deep would make
// any recursive walk over it overflow the stack), and numbers beyond the
// double range such as 1e400 (nlohmann throws an out_of_range error with no
// position).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace rl {

// The deepest legal scene nests 5 levels (spheres[i].material.albedo[k]); 64 leaves room
// for rubrics and grade records and keeps every recursive walk over a value shallow.
constexpr int kMaxJsonDepth = 64;

// Throws rl::Error "origin:3:14: syntax error: ...", "origin:1:70: values nest more than 64 deep",
// "origin:2:9: number 1e400 is out of range", "origin:4:1: NUL byte (is this a binary file?)".
nlohmann::json parseJsonText(const std::string& text, const std::string& origin);

// A value for a message, never recursive and never long: 12, "abc" (quoted and cut),
// true, null, "an array of 3", "an object with 2 keys".
std::string describeJsonValue(const nlohmann::json& value);

}  // namespace rl
