#include "shader/shader_library.h"

#include "core/error.h"
#include "core/paths.h"
#include "course/exercise_registry.h"
#include "shader/readiness.h"

namespace fs = std::filesystem;

namespace rl {

fs::path Implementation::fileFor(const std::string& exerciseFile) const {
    auto it = overrides.find(exerciseFile);
    return it != overrides.end() ? it->second : dir / exerciseFile;
}

bool isFrameworkFile(const fs::path& file) {
    if (isInside(file, shadersDir())) return true;
    for (const ExerciseInfo& e : frameworkUnits())
        if (isInside(file, courseDir() / e.id)) return true;
    return false;
}

IncludeResolver makeIncludeResolver(const Implementation& impl) {
    return [impl](const std::string& name, const fs::path& fromFile) -> fs::path {
        const std::string prefix = "exercise/";
        const bool fromFramework = isInside(fromFile, shadersDir());
        if (name.rfind(prefix, 0) == 0 && fromFramework) return impl.fileFor(name.substr(prefix.size()));
        // A unit that is no exercise of this course: its solution is framework code.
        const std::string unitPrefix = "unit/";
        if (name.rfind(unitPrefix, 0) == 0 && fromFramework) return courseDir() / name.substr(unitPrefix.size());
        fs::path relative(name);
        if (relative.is_absolute()) throw Error("absolute include paths are not allowed");
        const fs::path folder = fromFile.parent_path();
        const fs::path target = folder / relative;
        if (!isInside(target, folder.empty() ? fs::path(".") : folder))
            throw Error("refused: the file lies outside " + displayPath(folder) + "/");
        return target;
    };
}

std::string shaderPrelude(const ShaderDefines& defines, GlslDialect dialect) {
    std::string prelude = dialect == GlslDialect::Es300
                              ? "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                              : "#version 330 core\n";
    for (const auto& [name, value] : defines) prelude += "#define " + name + " " + value + "\n";
    return prelude;
}

AssembledSource assembleShader(const std::string& entry, const Implementation& impl, const ShaderDefines& defines,
                               GlslDialect dialect) {
    // Every file outside shaders/ is an exercise file: its errors are the author's.
    // exercises.glsl is written per implementation: the exercise files, with
    // what is not ready yet replaced by the framework's neutral value.
    // exercise_declarations.glsl and probe_dispatch.glsl come from the units.
    const int probed = probeExerciseOf(defines);
    GeneratedFiles generated{{"exercises.glsl", exercisesGlsl(readinessOf(impl, probed))},
                             {"exercise_declarations.glsl", exerciseDeclarationsGlsl()},
                             {"probe_dispatch.glsl", probeDispatchGlsl(probed)}};
    SourceAssembler assembler(makeIncludeResolver(impl), isFrameworkFile, std::move(generated));
    return assembler.assemble(shaderPrelude(defines, dialect), shadersDir() / entry);
}

ShaderProgram buildRayTracer(const Implementation& impl, const ShaderDefines& defines) {
    AssembledSource vertex = assembleShader("fullscreen.vert", impl, {});
    AssembledSource fragment = assembleShader("main.frag", impl, defines);
    return ShaderProgram(vertex, fragment);
}

}  // namespace rl
