#include "shader/program.h"

#include "shader/driver_log.h"
#include "shader/loop_guard.h"
#include "shader/source_checks.h"

#include <utility>

namespace rl {

namespace {
// How much of a driver message and of a source line a message shows: enough
// for any real message or line of code, while a 200,000-character
// identifier cannot flood the terminal.
constexpr std::size_t kMaxShownMessage = 400;
constexpr std::size_t kMaxShownSourceLine = 160;
// Errors printed for one failed build; the count of the rest follows. The
// first error is nearly always the cause: 200 undeclared identifiers printed
// 57 KB before this cap.
constexpr std::size_t kMaxShownErrors = 10;

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}
}  // namespace

std::string ShaderDiagnostic::format() const {
    std::string out;
    if (where.file.empty()) out = "<shader>: " + severity + ": ";
    else if (where.line <= 0) out = where.file + ": ";  // about the whole file: "D_GGX is missing (...)"
    else out = where.file + ":" + std::to_string(where.line) + ": " + severity + ": ";
    out += printable(oneLine(message), kMaxShownMessage);
    if (!sourceLine.empty()) out += "\n    " + printable(sourceLine, kMaxShownSourceLine);
    return out;
}

namespace {
std::string joinDiagnostics(const std::string& stage, const std::vector<ShaderDiagnostic>& list) {
    std::string out;
    std::size_t shown = 0, more = 0;
    const ShaderDiagnostic* previous = nullptr;
    for (const auto& d : list) {
        if (d.severity != "error") continue;
        if (previous && previous->where.file == d.where.file && previous->where.line == d.where.line &&
            previous->message == d.message)
            continue;  // the same error twice (drivers repeat them per use)
        previous = &d;
        if (shown == kMaxShownErrors) {
            ++more;
            continue;
        }
        out += (out.empty() ? "" : "\n") + d.format();
        ++shown;
    }
    if (more)
        out += "\n... and " + std::to_string(more) + " more error" + (more == 1 ? "" : "s") +
               " (fix the first one: the others often follow from it)";
    return out.empty() ? stage + " failed with no message from the driver" : out;
}
}  // namespace

ShaderError::ShaderError(std::string stage, std::vector<ShaderDiagnostic> diagnostics)
    : Error(joinDiagnostics(stage, diagnostics)), diagnostics_(std::move(diagnostics)) {}

std::vector<ShaderDiagnostic> mapDriverLog(const std::string& log, const AssembledSource& source) {
    std::vector<ShaderDiagnostic> out;
    for (const DriverMessage& m : parseDriverLog(log)) {
        ShaderDiagnostic d;
        d.severity = m.severity;
        d.message = m.text;
        if (auto where = source.locate(m.line)) {
            d.where = *where;
            d.sourceLine = source.authorLine(m.line);
            auto first = d.sourceLine.find_first_not_of(" \t");
            d.sourceLine = first == std::string::npos ? "" : d.sourceLine.substr(first);
        }
        explainLoopGuard(d);
        out.push_back(std::move(d));
    }
    explainDriverDiagnostics(out, source);
    return out;
}

GLuint compileShaderStage(GLenum stage, const std::string& text, std::string& log) {
    GLuint shader = gl::CreateShader(stage);
    const char* source = text.c_str();
    gl::ShaderSource(shader, 1, &source, nullptr);
    gl::CompileShader(shader);
    GLint ok = 0, length = 0;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    gl::GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    log.assign(std::size_t(std::max(length, 0)), '\0');
    if (length > 0) gl::GetShaderInfoLog(shader, length, nullptr, log.data());
    if (!ok) {
        gl::DeleteShader(shader);
        return 0;
    }
    return shader;
}

namespace {

GLuint compile(GLenum stage, const AssembledSource& source, std::vector<ShaderDiagnostic>& warnings) {
    std::string log;
    GLuint shader = compileShaderStage(stage, source.text, log);
    auto diagnostics = mapDriverLog(log, source);
    if (!shader) {
        if (diagnostics.empty()) diagnostics.push_back({{}, "error", log.empty() ? "compile failed" : log, ""});
        throw ShaderError(stage == GL_VERTEX_SHADER ? "vertex shader" : "fragment shader", std::move(diagnostics));
    }
    for (auto& d : diagnostics) warnings.push_back(std::move(d));
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const AssembledSource& vertex, const AssembledSource& fragment) : loops_(fragment.loops) {
    // What the host can tell before the driver: the exercises' contract,
    // names defined in two exercise files (shader/source_checks.h).
    for (const AssembledSource* source : {&vertex, &fragment}) {
        auto errors = checkExerciseSources(*source);
        if (!errors.empty())
            throw ShaderError(source == &vertex ? "vertex shader" : "fragment shader", std::move(errors));
    }
    GLuint vs = compile(GL_VERTEX_SHADER, vertex, warnings_);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragment, warnings_);
    } catch (...) {
        gl::DeleteShader(vs);
        throw;
    }
    id_ = gl::CreateProgram();
    gl::AttachShader(id_, vs);
    gl::AttachShader(id_, fs);
    gl::LinkProgram(id_);
    gl::DetachShader(id_, vs);
    gl::DetachShader(id_, fs);
    gl::DeleteShader(vs);
    gl::DeleteShader(fs);
    GLint ok = 0, length = 0;
    gl::GetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        gl::GetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 0)), '\0');
        if (length > 0) gl::GetProgramInfoLog(id_, length, nullptr, log.data());
        gl::DeleteProgram(id_);
        id_ = 0;
        auto diagnostics = mapDriverLog(log, fragment);
        if (diagnostics.empty()) diagnostics.push_back({{}, "error", "link failed: " + log, ""});
        for (auto& d : diagnostics) d.severity = "error";
        throw ShaderError("link", std::move(diagnostics));
    }
}

namespace {
// A program deleted while current is only freed at the next glUseProgram,
// and its name is no longer valid: a caller that saved GL_CURRENT_PROGRAM to
// restore it (Dear ImGui's renderer in the live view) would ask for a program
// that no longer exists (GL_INVALID_VALUE, seen when a hot reload drops the
// still picture's program). So none of ours stays current when it goes.
void deleteProgram(GLuint id) {
    GLint current = 0;
    gl::GetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) == id) gl::UseProgram(0);
    gl::DeleteProgram(id);
}
}  // namespace

ShaderProgram::~ShaderProgram() {
    if (id_) deleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(std::exchange(other.id_, 0)), locations_(std::move(other.locations_)), warnings_(std::move(other.warnings_)),
      loops_(std::move(other.loops_)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_) deleteProgram(id_);
        id_ = std::exchange(other.id_, 0);
        locations_ = std::move(other.locations_);
        warnings_ = std::move(other.warnings_);
        loops_ = std::move(other.loops_);
    }
    return *this;
}

GLint ShaderProgram::uniform(const std::string& name) const {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint location = gl::GetUniformLocation(id_, name.c_str());
    locations_.emplace(name, location);
    return location;
}

}  // namespace rl
