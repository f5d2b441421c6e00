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
    bool wipe = false;               // split screen between --impl (left) and --compare (right)
    double divider = 0.5;            // wipe position, fraction of the width from the left
    bool continuous = false;         // render every frame even when nothing changed (fps measurements)
    bool adaptiveResolution = true;  // render fewer pixels while the camera moves
    bool saveCamera = true;          // "save scene" writes the trackball's view as the camera
    std::string savePath;            // where "save scene" writes; the scene file by default
};

// Changes of one frame, from the panel or a key, that the window acts on.
struct ViewRequests {
    bool sceneEdited = false;  // re-upload uniforms (never recompiles)
    bool redraw = false;       // the view, the wipe: render again
    int openPreset = -1;       // index into presetScenes()
    bool save = false;
    bool resetCamera = false;
    bool screenshot = false;
    bool screenshotWithUi = false;
    bool toggleFullscreen = false;
    bool quit = false;
    float uiScale = 0;  // > 0: set the UI scale to this
};

}  // namespace rl
