// A linked GLSL program built from assembled sources. The host's checks of
// the exercise files (shader/source_checks.h) and the driver's compile and
// link errors become rl::ShaderError whose message is, per error (at most
// 10, then a count of the rest),
//     path/to/file.glsl:LINE: error: message
//         the source line
// in the files the author wrote, whatever the driver's log format.
#pragma once

#include "core/error.h"
#include "gl/gl_api.h"
#include "shader/source_assembler.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace rl {

struct ShaderDiagnostic {
    SourceLocation where;   // file "" when the driver gave no line
    std::string severity;   // "error" or "warning"
    std::string message;    // the driver's text without its location prefix
    std::string sourceLine; // the line the author wrote, for context
    std::string format() const;  // "file:line: error: message\n    source line"
};

class ShaderError : public Error {
public:
    ShaderError(std::string stage, std::vector<ShaderDiagnostic> diagnostics);
    const std::vector<ShaderDiagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::vector<ShaderDiagnostic> diagnostics_;
};

// Maps a driver's info log for `source` back to the author's files, and
// moves errors the driver placed after the mistake into the exercise file.
std::vector<ShaderDiagnostic> mapDriverLog(const std::string& log, const AssembledSource& source);

// Compiles one shader stage; its id (0 when it did not compile: then
// deleted), `log` the driver's info log.
GLuint compileShaderStage(GLenum stage, const std::string& text, std::string& log);

class ShaderProgram {
public:
    ShaderProgram() = default;
    // Throws ShaderError on compile or link failure.
    ShaderProgram(const AssembledSource& vertex, const AssembledSource& fragment);
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    GLuint id() const { return id_; }
    bool valid() const { return id_ != 0; }
    // Location of a uniform, cached after the first lookup; -1 when the
    // driver optimised it away (setting it is then a no-op, as GL defines).
    GLint uniform(const std::string& name) const;
    // Warnings the driver printed for a program that did build.
    const std::vector<ShaderDiagnostic>& warnings() const { return warnings_; }
    // The fragment shader's guarded loops (shader/loop_guard.h), loop ID - 1 first.
    const std::vector<SourceLocation>& guardedLoops() const { return loops_; }

private:
    GLuint id_ = 0;
    mutable std::unordered_map<std::string, GLint> locations_;
    std::vector<ShaderDiagnostic> warnings_;
    std::vector<SourceLocation> loops_;
};

}  // namespace rl
