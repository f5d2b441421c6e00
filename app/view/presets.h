// The course figures, two kinds:
//  * scene presets: files in scenes/presets/ (numbered in teaching order:
//    roughness 0..1, metallic 0..1, gamma off/on, exposure low/high,
//    reflections off/on), then the scenes in scenes/ (lecture, dielectric
//    and metal rows). The panel opens them all, PageUp/PageDown the
//    figures of scenes/presets/ in their order; `raylab
//    render scenes/presets/...` renders the same figure headless.
//  * setting presets: one-click changes to the scene on screen (gamma off,
//    2.2, sRGB; exposure low, normal, high; reflections off, on).
#pragma once

#include "core/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

// Sorted, presets/ first; empty when the folders are missing.
std::vector<std::filesystem::path> presetScenes();
// How many of `presets` (presetScenes()) are course figures, the files of
// scenes/presets/ (they come first): PageDown and PageUp step through these,
// in their numbered order; the scenes after them are opened from the panel.
int presetFigureCount(const std::vector<std::filesystem::path>& presets);
// "roughness 0 to 1" for "scenes/presets/01-roughness-0-to-1.json".
std::string presetTitle(const std::filesystem::path& file);

struct SettingPreset {
    const char* group;  // "Gamma", "Exposure", "Reflections": one row of buttons each
    const char* label;  // the button
    // Changes `scene`; `fromFile` is the scene as its file has it (for
    // "reflections on", which restores the file's bounce count).
    void (*apply)(Scene& scene, const Scene& fromFile);
};
const std::vector<SettingPreset>& settingPresets();

}  // namespace rl
