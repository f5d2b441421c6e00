// The scene shown in the window: loaded from its file, edited in the panel,
// reloaded when the file changes. A reload that fails keeps the last good
// scene and leaves the one-line error in error() until a reload succeeds.
#pragma once

#include "core/scene.h"

#include <string>
#include <vector>

namespace rl {

class LiveScene {
public:
    // `path` empty: the embedded default scene (nothing to reload). Throws
    // rl::Error when the first load fails: there is no last good scene yet.
    explicit LiveScene(const std::string& path);

    // Reads the file again. True: scene() is the file's (panel edits are
    // replaced). False: scene() is unchanged and error() says why.
    bool reload();
    // Switches to another file (a preset); same contract as reload(), and on
    // failure path() stays the old one.
    bool open(const std::string& path);

    Scene& scene() { return scene_; }  // the panel edits it in place
    const Scene& scene() const { return scene_; }
    // The scene as its file has it, without the panel's edits.
    const Scene& fromFile() const { return fromFile_; }
    const std::string& path() const { return path_; }  // "" for the embedded default
    const std::string& error() const { return error_; }
    // Warnings of the last successful load (unknown keys), one line each.
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    std::string path_;
    Scene scene_;
    Scene fromFile_;
    std::string error_;
    std::vector<std::string> warnings_;
};

}  // namespace rl
