// Named cameras of the live view: Ctrl+F1..Ctrl+F8 store the current view
// under "F1".."F8", F1..F8 recall it. They live in a file beside the scene,
// SCENE.cameras.json (cameras.json in the working directory for the
// embedded scene), so viewpoints prepared before a lecture are there in the
// hall; the scene file itself is never touched.
#pragma once

#include "core/scene.h"

#include <map>
#include <optional>
#include <string>

namespace rl {

// "scenes/lecture.json" -> "scenes/lecture.cameras.json"; "" -> "cameras.json".
std::string namedCamerasFile(const std::string& scenePath);

class NamedCameras {
public:
    // Reads `file` when it exists. A file that cannot be read leaves the set
    // empty and says why in error() (one line naming the file); it is only
    // replaced when a camera is stored.
    explicit NamedCameras(std::string file);

    const std::string& file() const { return file_; }
    const std::string& error() const { return error_; }
    std::optional<Camera> get(const std::string& name) const;
    // Stores and writes the whole file (a temporary renamed over it).
    // Throws rl::Error naming the file when it cannot be written.
    void set(const std::string& name, const Camera& camera);

private:
    std::string file_;
    std::string error_;
    std::map<std::string, Camera> cameras_;
};

}  // namespace rl
