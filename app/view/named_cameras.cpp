#include "view/named_cameras.h"

#include "core/error.h"
#include "core/file_io.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace rl {
namespace {

glm::dvec3 vec3From(const nlohmann::json& j) {
    if (!j.is_array() || j.size() != 3) throw Error("expected [x, y, z]");
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}
nlohmann::json jsonOf(glm::dvec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace

std::string namedCamerasFile(const std::string& scenePath) {
    if (scenePath.empty()) return "cameras.json";
    fs::path p(scenePath);
    return (p.parent_path() / (p.stem().string() + ".cameras.json")).string();
}

NamedCameras::NamedCameras(std::string file) : file_(std::move(file)) {
    std::error_code ec;
    if (!fs::exists(file_, ec)) return;  // none stored yet
    try {
        const nlohmann::json j = nlohmann::json::parse(readRegularFile(file_, kMaxTextFileBytes, "the named cameras"));
        for (const auto& [name, c] : j.at("cameras").items()) {
            Camera camera;
            camera.position = vec3From(c.at("position"));
            camera.target = vec3From(c.at("target"));
            camera.up = vec3From(c.at("up"));
            cameras_[name] = camera;
        }
    } catch (const std::exception& e) {
        cameras_.clear();
        error_ = file_ + ": named cameras not read (" + e.what() + ")";
    }
}

std::optional<Camera> NamedCameras::get(const std::string& name) const {
    auto it = cameras_.find(name);
    if (it == cameras_.end()) return std::nullopt;
    return it->second;
}

void NamedCameras::set(const std::string& name, const Camera& camera) {
    cameras_[name] = camera;
    nlohmann::json cameras = nlohmann::json::object();
    for (const auto& [n, c] : cameras_)
        cameras[n] = {{"position", jsonOf(c.position)}, {"target", jsonOf(c.target)}, {"up", jsonOf(c.up)}};
    const nlohmann::json j = {{"cameras", cameras}};
    writeFileAtomic(file_, j.dump(2) + "\n", WriteOptions{"the named cameras"});  // never half a file
    error_.clear();
}

}  // namespace rl
