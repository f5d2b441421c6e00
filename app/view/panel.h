// The ImGui panel: every material and light of the scene, the display and
// render settings, the teaching view, presets, the wipe, frame times, UI
// scale and saving. Edits change the scene in place and are reported in
// ViewRequests; the window re-uploads uniforms, nothing is recompiled.
#pragma once

#include "core/scene.h"
#include "view/layout_report.h"
#include "view/view_state.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

// Facts the panel shows but does not change.
struct PanelInfo {
    std::string device;             // GL vendor | renderer | version
    std::string scenePath;          // "" for the embedded default scene
    std::string left, right;        // implementation labels; right empty without --compare
    double gpuMs = 0, frameMs = 0;  // recent medians; 0 = not measured yet
    int renderWidth = 0, renderHeight = 0, windowWidth = 0, windowHeight = 0;
    const std::vector<std::filesystem::path>* presets = nullptr;
    int currentPreset = -1;  // index into presets, -1 when the scene is none of them
    float uiScale = 1;
    std::string status;  // the last save or screenshot, one line
    // The window clears the panel's rectangle to its background colour
    // itself (a scissored clear: on llvmpipe a fill of memory, where ImGui's
    // background is a textured, blended quad over ~700k pixels at UI scale
    // 2 on 1080p): the panel then draws no background of its own.
    bool backgroundCleared = false;
};

// Where the panel starts, in window (ImGui) units: top left, 340 x the UI
// scale wide but at most 45% of the window, the window's height less the
// margins. drawPanel() puts it back there when the scale or the window size
// changes.
struct PanelRect {
    float x = 0, y = 0, width = 0, height = 0;
};
PanelRect panelRect(float windowWidth, float windowHeight, float uiScale);

// Where the panel's parts went this frame, window units (empty: not shown).
struct PanelRects {
    LayoutRect panel;       // the panel's window (or the strip)
    LayoutRect title;       // its title text, whole (cut when wider than the title bar)
    LayoutRect titleBar;    // the room for it: the title bar less the close button
    LayoutRect viewCombo;   // the teaching view's dropdown: the room for its text
    LayoutRect viewText;    // the current view's name in it, whole
    LayoutRect askedPixel;  // the asked pixel's box
    LayoutRect content;     // the room for the rows: the panel less its padding and scroll bar
    LayoutRect rows;        // the rows as drawn: from content's left to the right edge of the widest (cut beyond content)
};

// Draws the panel (when state.showPanel) and returns what the user asked for.
ViewRequests drawPanel(Scene& scene, const Scene& fromFile, ViewState& state, const PanelInfo& info,
                       PanelRects* rects = nullptr);

}  // namespace rl
