// Which GLSL files make a shader: the framework in shaders/, plus one file
// per exercise from an implementation folder (--impl DIR), optionally with
// single exercises taken from elsewhere (a check puts the student's file for
// one exercise beside the solutions for all others). Like glslViewer's -I,
// the framework names "exercise/05-ggx.glsl" and the host picks the file.
#pragma once

#include "shader/program.h"
#include "shader/source_assembler.h"

#include <filesystem>
#include <map>
#include <string>

namespace rl {

struct Implementation {
    std::filesystem::path dir;  // exercises/, solutions/, a student's folder
    // Exercise file name ("05-ggx.glsl") -> file used instead of dir/name.
    std::map<std::string, std::filesystem::path> overrides;

    std::filesystem::path fileFor(const std::string& exerciseFile) const;
};

// Compile-time choices: #define NAME VALUE lines after #version.
using ShaderDefines = std::map<std::string, std::string>;

// Resolves `#include "..."`: "exercise/NAME" from the implementation; any
// other name relative to the including file, never leaving the folder that
// file belongs to (shaders/ for the framework, an implementation's own
// folder for exercise files), so a student's file cannot read anything else.
IncludeResolver makeIncludeResolver(const Implementation& impl);

// True for the framework's files: shaders/, and the solutions of the units
// that are no exercise of this course (course/manifest.txt). Errors in any
// other file are the author's.
bool isFrameworkFile(const std::filesystem::path& file);

// Which GLSL a program is compiled as: desktop GLSL 3.30 core (the native
// build), or GLSL ES 3.00 (WebGL2's language, and the strict rules of
// stricter drivers), whose prelude also sets highp precision.
enum class GlslDialect { Desktop330, Es300 };
// The dialect of this build: the browser edition (web/, built with
// emscripten) speaks WebGL2's GLSL ES 3.00, the native build desktop 3.30.
#ifdef __EMSCRIPTEN__
inline constexpr GlslDialect kHostDialect = GlslDialect::Es300;
#else
inline constexpr GlslDialect kHostDialect = GlslDialect::Desktop330;
#endif

// The #version line and defines every raylab shader starts with.
std::string shaderPrelude(const ShaderDefines& defines, GlslDialect dialect = kHostDialect);

// Assembles a framework entry point (e.g. "main.frag") with an implementation.
AssembledSource assembleShader(const std::string& entry, const Implementation& impl, const ShaderDefines& defines,
                               GlslDialect dialect = kHostDialect);

// The full-screen ray tracer: fullscreen.vert + main.frag. Throws ShaderError
// (compile/link, mapped to file:line) or rl::Error (missing file, bad include).
ShaderProgram buildRayTracer(const Implementation& impl, const ShaderDefines& defines = {});

}  // namespace rl
