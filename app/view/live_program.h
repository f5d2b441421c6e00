// The ray tracer of one implementation, kept alive across edits: rebuild()
// assembles and compiles the sources again; when that fails, the last good
// program stays in use and error() says why (glslViewer's "revert to the
// previous shader"), until a later rebuild succeeds.
#pragma once

#include "shader/program.h"
#include "shader/shader_library.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rl {

class LiveProgram {
public:
    // `defines`: the model variant's (render/shader_config.h modelDefines).
    LiveProgram(Implementation impl, std::string label, ShaderDefines defines = {});

    // Changes the defines for the next rebuild(); true when they differ from
    // the current ones (then the caller rebuilds: a scene with another model).
    bool setDefines(const ShaderDefines& defines);

    // True when a new program is in use. False: error() holds the message,
    // as rl::ShaderError formats it ("file:line: error: message\n    source line").
    bool rebuild();

    // The last program that built; nullptr until one has.
    const ShaderProgram* program() const { return program_ ? &*program_ : nullptr; }
    const std::string& error() const { return error_; }
    const std::string& label() const { return label_; }
    const Implementation& implementation() const { return impl_; }
    // Every file the last assembly read (framework, includes, exercise files),
    // for the file watcher. Before any assembly succeeded: every .glsl file
    // the implementation could use, so that fixing any of them is noticed.
    const std::vector<std::filesystem::path>& files() const { return files_; }
    double lastBuildMs() const { return lastBuildMs_; }

private:
    Implementation impl_;
    std::string label_;
    ShaderDefines defines_;
    std::optional<ShaderProgram> program_;
    std::string error_;
    std::vector<std::filesystem::path> files_;
    double lastBuildMs_ = 0;
};

}  // namespace rl
