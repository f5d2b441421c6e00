// Scene files: JSON as in docs/scene-format.md, read with
// nlohmann-json and validated field by field. Every problem is one line
// naming the file (and line:column for syntax errors, the field path for bad
// values); unknown keys are warnings, not errors.
#pragma once

#include "core/scene.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rl {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> warnings;  // "scenes/x.json: unknown key 'spheres[0].colour' (ignored)"
};

// Throws rl::Error: "scenes/x.json:3:14: syntax error: ...", "scenes/x.json: spheres[3].radius must be > 0",
// "scenes/x.json: file not found", "... is a directory", "... is empty".
LoadedScene loadSceneFile(const std::string& path);
// `origin` names the text in messages (a path, or "<default>").
LoadedScene parseScene(const std::string& text, const std::string& origin);

// The embedded default scene (used when no scene file is given).
const char* defaultSceneJson();
Scene defaultScene();

// Back to JSON with every field written out (the live panel's "save").
nlohmann::json sceneToJson(const Scene& scene);
void saveSceneFile(const Scene& scene, const std::string& path);

// Names used in files and on the command line.
std::string toneMapName(ToneMap op);

}  // namespace rl
