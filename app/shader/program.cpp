#include "shader/program.h"

#include "shader/driver_log.h"

#include <utility>

namespace rl {

std::string ShaderDiagnostic::format() const {
    std::string out = where.file.empty() ? std::string("<shader>") : where.file + ":" + std::to_string(where.line);
    out += ": " + severity + ": " + message;
    if (!sourceLine.empty()) out += "\n    " + sourceLine;
    return out;
}

namespace {
std::string joinDiagnostics(const std::string& stage, const std::vector<ShaderDiagnostic>& list) {
    std::string out;
    for (const auto& d : list)
        if (d.severity == "error") out += (out.empty() ? "" : "\n") + d.format();
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
            d.sourceLine = source.lineText(m.line);
            auto first = d.sourceLine.find_first_not_of(" \t");
            d.sourceLine = first == std::string::npos ? "" : d.sourceLine.substr(first);
        }
        out.push_back(std::move(d));
    }
    return out;
}

namespace {

GLuint compile(GLenum stage, const AssembledSource& source, std::vector<ShaderDiagnostic>& warnings) {
    GLuint shader = gl::CreateShader(stage);
    const char* text = source.text.c_str();
    gl::ShaderSource(shader, 1, &text, nullptr);
    gl::CompileShader(shader);
    GLint ok = 0, length = 0;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    gl::GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 0)), '\0');
    if (length > 0) gl::GetShaderInfoLog(shader, length, nullptr, log.data());
    auto diagnostics = mapDriverLog(log, source);
    if (!ok) {
        gl::DeleteShader(shader);
        if (diagnostics.empty()) diagnostics.push_back({{}, "error", log.empty() ? "compile failed" : log, ""});
        throw ShaderError(stage == GL_VERTEX_SHADER ? "vertex shader" : "fragment shader", std::move(diagnostics));
    }
    for (auto& d : diagnostics) warnings.push_back(std::move(d));
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const AssembledSource& vertex, const AssembledSource& fragment) {
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

ShaderProgram::~ShaderProgram() {
    if (id_) gl::DeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(std::exchange(other.id_, 0)), locations_(std::move(other.locations_)), warnings_(std::move(other.warnings_)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_) gl::DeleteProgram(id_);
        id_ = std::exchange(other.id_, 0);
        locations_ = std::move(other.locations_);
        warnings_ = std::move(other.warnings_);
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
