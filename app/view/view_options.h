// The command line of `raylab view` (app/commands/view_command.cpp).
#pragma once

#include "render/pixel_debugger.h"
#include "shader/shader_library.h"

#include <functional>
#include <string>

namespace rl {

struct ViewOptions {
    std::string scene;           // scene file; "" = the embedded default scene
    std::string impl;            // exercise folder; "" = solutions/ (exercises/ in a student edition)
    std::string compare;         // second folder for the wipe; "" = none
    std::string compareModel;    // "blinn-phong" or "pbr": the wipe's right side uses that model; "" = the scene's
    int width = 0, height = 0;   // window size (--size); 0 = the scene's render size
    std::string view = "final";  // teaching view at start, as `render --view`
    std::string script;          // scripted input (input_script.h); "" = none
    int frames = 0;              // > 0: run this many frames (after the script) and exit
    std::string screenshot;      // with --frames: the last frame's picture as PNG
    bool stats = false;          // print the median frame time at exit (always with --frames)
    bool fullscreen = false;     // start fullscreen
    bool hidePanel = false;      // start with the panel hidden (a clean picture)
    bool panelStrip = false;     // start with the panel folded to the presenter's strip
    bool sideBySide = false;     // start with two full pictures side by side (needs --compare or --compare-model)
    bool hideCaptions = false;   // start without the caption and colour bar on the picture
    float uiScale = 0;           // 0 = the monitor's content scale
    bool generic = false;        // draw with the generic program (model defines only), as before the live specialisation
    // The asked pixel's checker hint (checks/pixel_hint.h, a layer above the
    // view: view_command.cpp hands it in); unset: the debugger names the
    // exercise and its handout only.
    std::function<void(PixelDebug&, const Implementation&)> probeHint;
};

}  // namespace rl
