// The ray tracer of one implementation, kept alive across edits: rebuild()
// assembles and compiles the sources again; when that fails, the last good
// program stays in use and error() says why (glslViewer's "revert to the
// previous shader"), until a later rebuild succeeds.
//
// The live view needs a few programs of the same sources (one per set of
// defines: the picture and the teaching views, render/define_table.h), so
// each one built is kept until the sources change: switching views back
// and forth compiles each program once.
#pragma once

#include "core/scene.h"
#include "render/gl_renderer.h"
#include "render/scene_uniforms.h"
#include "shader/program.h"
#include "shader/shader_library.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rl {

class LiveProgram {
public:
    // `defines`: the model variant's (render/define_table.h).
    LiveProgram(Implementation impl, std::string label, ShaderDefines defines = {});

    // Selects the program of `defines`. Returns true when it is not built
    // yet (then the caller calls build(): another view, structure or model);
    // false when it is in use already or was built before (then it is in use
    // now, nothing compiled).
    bool setDefines(const ShaderDefines& defines);

    // The sources changed: every kept program is dropped and the current
    // defines' program is built again. True when a new program is in use.
    // False: error() holds the message, as rl::ShaderError formats it
    // ("file:line: error: message\n    source line").
    bool rebuild();
    // Builds the current defines' program from the same sources (after
    // setDefines() returned true), keeping the others.
    bool build();

    // The last program that built; nullptr until one has.
    const ShaderProgram* program() const { return program_.get(); }
    const ShaderDefines& defines() const { return defines_; }
    // How many programs are kept (one per set of defines built since the
    // sources last changed).
    std::size_t keptPrograms() const { return built_.size(); }
    const std::string& error() const { return error_; }
    const std::string& label() const { return label_; }
    const Implementation& implementation() const { return impl_; }
    // Every file the last assembly read (framework, includes, exercise files),
    // for the file watcher. Before any assembly succeeded: every .glsl file
    // the implementation could use, so that fixing any of them is noticed.
    const std::vector<std::filesystem::path>& files() const { return files_; }
    double lastBuildMs() const { return lastBuildMs_; }

    // The still picture's program (Purpose::LiveStill, render/define_table.h:
    // the scene's numbers compiled in, the camera a uniform), with its sky
    // program, for `defines` (the caller's definesFor(..., LiveStill)): built
    // from the same sources as program(), whatever the files are. Returns
    // nullptr when those defines are not built yet and `mayBuild` is false
    // (a slider moving: the caller draws program() meanwhile and asks again
    // when the hand stops), or when they do not build (then program() draws
    // it). Sets `built` when it compiled one.
    PictureProgram* still(const ShaderDefines& defines, bool mayBuild, bool& built);
    // Still programs compiled since the start.
    int stillBuilds() const { return stillBuilds_; }

private:
    Implementation impl_;
    std::string label_;
    ShaderDefines defines_;
    std::shared_ptr<const ShaderProgram> program_;  // in use: the last that built
    std::map<ShaderDefines, std::shared_ptr<const ShaderProgram>> built_;  // since the sources last changed
    std::string error_;
    std::vector<std::filesystem::path> files_;
    double lastBuildMs_ = 0;
    ShaderDefines stillDefines_, failedDefines_;
    std::unique_ptr<PictureProgram> still_;
    int stillBuilds_ = 0;
};

}  // namespace rl
