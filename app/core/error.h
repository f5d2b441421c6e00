// The one error type of raylab: a message meant for the user, already
// formatted as "file:line: message" where a file is involved. Commands catch
// it at the top, print it on one line and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace rl {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rl
