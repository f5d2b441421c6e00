// What the viewer shows besides the scene: the teaching view, the wipe, the
// overlays. The panel and the keys change it; the window reads it each frame.
#pragma once

#include "render/scene_uniforms.h"

#include <string>

namespace rl {

// Exposure range of the panel and the Up/Down keys: six stops either side of
// 1, beyond any figure of the course, short of float overflow in the tone map.
constexpr double kMinExposure = 1.0 / 64.0;
constexpr double kMaxExposure = 64.0;

struct ViewState {
    View view = View::Final;         // teaching view (keys 0..9)
    int viewBounce = 1;              // k of view 9: 1 = the first reflection, the first one worth looking at
    bool showPanel = true;           // Tab
    bool showHelp = false;           // H
    int helpPage = 0;                // H again: the next page of the help; after the last, closed
    int helpPages = 1;               // as the help was last drawn (drawHelpOverlay)
    bool showCaptions = true;        // K: caption and colour bar on the picture (caption_layer.h)
    bool pickMode = false;           // I: a left click asks the pixel (as Ctrl+click)
    std::string pickedText;          // the last asked pixel's terms, for the panel
    int pickedSphere = -1;           // its primary hit's sphere (0-based), -1 = none
    bool revealPicked = false;       // the panel opens that sphere once
    bool turntable = false;          // T: left drag orbits as a turntable (no roll) instead of the arcball
    bool wipe = false;               // split screen between --impl (left) and --compare (right)
    bool sideBySide = false;         // X: two full pictures side by side instead of the wipe
    double divider = 0.5;            // wipe position, fraction of the width from the left
    bool continuous = false;         // render every frame even when nothing changed (fps measurements)
    bool adaptiveResolution = true;  // render fewer pixels while the camera moves
    bool saveCamera = true;          // "save scene" writes the trackball's view as the camera
    std::string savePath;            // where "save scene" writes: a new file by default (scene_patch.h)
    bool panelStrip = false;         // the panel folded to a narrow strip (presenter layout)
    bool askOverwrite = false;       // the panel asks before "save" writes over a bundled scene
    // The UI scale and window size the panel was last placed for (panel.cpp).
    float panelLayoutScale = 0, panelLayoutWidth = 0, panelLayoutHeight = 0;
};

// Changes of one frame, from the panel or a key, that the window acts on.
struct ViewRequests {
    bool sceneEdited = false;  // re-upload uniforms (never recompiles)
    bool redraw = false;       // the view, the wipe: render again
    int openPreset = -1;       // index into presetScenes()
    bool save = false;
    bool saveConfirmed = false;  // "overwrite" answered for a bundled scene
    bool resetCamera = false;
    bool screenshot = false;
    bool screenshotWithUi = false;
    bool toggleFullscreen = false;
    bool quit = false;
    float uiScale = 0;  // > 0: set the UI scale to this
};

}  // namespace rl
