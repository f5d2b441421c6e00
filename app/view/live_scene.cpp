#include "view/live_scene.h"

#include "core/error.h"
#include "core/scene_io.h"

namespace rl {

LiveScene::LiveScene(const std::string& path) : path_(path) {
    LoadedScene loaded = path.empty() ? LoadedScene{defaultScene(), {}} : loadSceneFile(path);
    scene_ = fromFile_ = loaded.scene;
    warnings_ = loaded.warnings;
}

bool LiveScene::reload() {
    if (path_.empty()) return true;
    return open(path_);
}

bool LiveScene::open(const std::string& path) {
    try {
        LoadedScene loaded = loadSceneFile(path);
        scene_ = fromFile_ = loaded.scene;
        warnings_ = loaded.warnings;
        path_ = path;
        error_.clear();
        return true;
    } catch (const Error& e) {
        error_ = e.what();
        return false;
    }
}

}  // namespace rl
