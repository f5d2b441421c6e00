#include "view/live_program.h"

#include "core/error.h"
#include "core/paths.h"

#include <algorithm>
#include <chrono>

namespace fs = std::filesystem;

namespace rl {
namespace {

// Every .glsl file directly in `dir`: the fallback watch list.
void addGlslFiles(const fs::path& dir, std::vector<fs::path>& out) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".glsl" || entry.path().extension() == ".frag" ||
            entry.path().extension() == ".vert")
            out.push_back(entry.path());
}

}  // namespace

LiveProgram::LiveProgram(Implementation impl, std::string label, ShaderDefines defines)
    : impl_(std::move(impl)), label_(std::move(label)), defines_(std::move(defines)) {
    addGlslFiles(shadersDir(), files_);
    addGlslFiles(impl_.dir, files_);
    for (const auto& [name, file] : impl_.overrides) files_.push_back(file);
}

bool LiveProgram::setDefines(const ShaderDefines& defines) {
    if (defines == defines_ && program_) return false;
    defines_ = defines;
    auto kept = built_.find(defines);
    if (kept == built_.end()) return true;
    program_ = kept->second;
    return false;
}

bool LiveProgram::rebuild() {
    built_.clear();  // from the old sources; the one in use stays until a new one builds
    still_.reset();  // built again from the new sources when the picture is still
    stillDefines_.clear();
    failedDefines_.clear();
    return build();
}

bool LiveProgram::build() {
    const auto start = std::chrono::steady_clock::now();
    try {
        AssembledSource vertex = assembleShader("fullscreen.vert", impl_, {});
        AssembledSource fragment = assembleShader("main.frag", impl_, defines_);
        std::vector<fs::path> files = vertex.files;
        for (const auto& f : fragment.files)
            if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
        files_ = std::move(files);  // known even when the compile below fails
        program_ = std::make_shared<const ShaderProgram>(vertex, fragment);
        built_[defines_] = program_;
        error_.clear();
    } catch (const Error& e) {
        error_ = e.what();
    }
    lastBuildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return error_.empty();
}

PictureProgram* LiveProgram::still(const ShaderDefines& defines, bool mayBuild, bool& built) {
    built = false;
    if (!still_ || defines != stillDefines_) {
        if (!mayBuild || defines == failedDefines_) return nullptr;
        const auto start = std::chrono::steady_clock::now();
        try {
            still_ = std::make_unique<PictureProgram>(buildPictureProgram(impl_, defines));
            stillDefines_ = defines;
            ++stillBuilds_;
            built = true;
        } catch (const Error&) {  // beyond the driver's limits: the structure's program draws it
            failedDefines_ = defines;
            return nullptr;
        }
        lastBuildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    return still_.get();
}

}  // namespace rl
