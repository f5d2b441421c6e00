#include "view/presets.h"

#include "core/paths.h"

#include <algorithm>
#include <cctype>

namespace fs = std::filesystem;

namespace rl {
namespace {

std::vector<fs::path> jsonFilesIn(const fs::path& dir) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        // Scenes only: not the JSON Schema of the scene format, not the
        // named cameras stored beside a scene (named_cameras.h).
        const std::string name = entry.path().filename().string();
        const auto endsWith = [&](const std::string& tail) {
            return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
        };
        if (entry.is_regular_file(ec) && entry.path().extension() == ".json" && !endsWith(".schema.json") &&
            !endsWith(".cameras.json"))
            out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Exposure presets, in stops from the scene's 1.0: two stops down and up
// (x0.25, x4) are the course figure, far enough apart that the tone map's
// highlight roll-off and the lost shadow detail are both obvious.
constexpr double kLowExposure = 0.25;
constexpr double kHighExposure = 4.0;
// Bounces for "reflections on" when the scene file has none: 2, the spec's
// default (a reflection of a reflection is where the picture stops changing).
constexpr int kDefaultBounces = 2;

}  // namespace

std::vector<fs::path> presetScenes() {
    std::vector<fs::path> out = jsonFilesIn(scenesDir() / "presets");
    for (const auto& f : jsonFilesIn(scenesDir())) out.push_back(f);
    return out;
}

int presetFigureCount(const std::vector<fs::path>& presets) {
    int n = 0;
    while (n < int(presets.size()) && presets[std::size_t(n)].parent_path().filename() == "presets") ++n;
    return n;
}

std::string presetTitle(const fs::path& file) {
    std::string stem = file.stem().string();
    // "01-roughness-0-to-1": drop the ordering number, dashes to spaces.
    std::size_t start = 0;
    while (start < stem.size() && std::isdigit(static_cast<unsigned char>(stem[start]))) ++start;
    if (start > 0 && start < stem.size() && stem[start] == '-') stem = stem.substr(start + 1);
    std::replace(stem.begin(), stem.end(), '-', ' ');
    return stem;
}

const std::vector<SettingPreset>& settingPresets() {
    static const std::vector<SettingPreset> list = {
        {"Gamma", "off (1.0)", [](Scene& s, const Scene&) { s.render.gamma = 1.0, s.render.srgb = false; }},
        {"Gamma", "2.2", [](Scene& s, const Scene&) { s.render.gamma = 2.2, s.render.srgb = false; }},
        {"Gamma", "sRGB", [](Scene& s, const Scene&) { s.render.srgb = true; }},
        {"Exposure", "low (x0.25)", [](Scene& s, const Scene&) { s.render.exposure = kLowExposure; }},
        {"Exposure", "1", [](Scene& s, const Scene&) { s.render.exposure = 1.0; }},
        {"Exposure", "high (x4)", [](Scene& s, const Scene&) { s.render.exposure = kHighExposure; }},
        {"Reflections", "off", [](Scene& s, const Scene&) { s.render.maxBounces = 0; }},
        {"Reflections", "on",
         [](Scene& s, const Scene& file) {
             s.render.maxBounces = file.render.maxBounces > 0 ? file.render.maxBounces : kDefaultBounces;
         }},
    };
    return list;
}

}  // namespace rl
