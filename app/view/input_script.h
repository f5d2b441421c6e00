// Scripted input for `raylab view --script FILE`: what a test or a recorded
// demo does to the window, one command a line, run in order, one step per
// frame. Frames are counted, not timed, so a script does the same on a fast
// GPU and on llvmpipe; only `sleep` and `wait-reload` use the clock.
//
//   # comment
//   wait 3                      render 3 frames
//   sleep 0.5                   keep rendering for 0.5 s
//   wait-reload 5               render until a hot reload (shader or scene, good or
//                               bad) is applied that was not yet applied when the
//                               previous command finished; an error after 5 s
//   drag 80 60 120 60 [left|right|middle] [STEPS]
//                               press at (80,60), move to (120,60) over STEPS
//                               frames (default 4), release; framebuffer pixels,
//                               origin top-left, as rl::Trackball takes them
//   scroll 2                    wheel steps (positive: zoom in)
//   key R                       press a key (names as in the help: R, 6, F11, Ctrl+S, Up)
//   view normals                select a teaching view by name (as render --view)
//   divider 0.3                 put the wipe divider at 30% of the width
//   pick 200 150                ask the pixel at (200,150) (as Ctrl+click): its terms from
//                               the CPU reference, printed and shown in the panel
//   slide roughness 0.1 0.9 [STEPS]
//                               drag a panel slider from 0.1 to 0.9 over STEPS frames
//                               (default 4), as a hand on the slider does: roughness,
//                               metallic (of spheres[0]), exposure, env-intensity or
//                               env-rotation (degrees; a scene with an environment)
//   resize 320 240              set the window size (screen coordinates)
//   screenshot out.png [ui]     write the picture (or, with `ui`, the whole window)
//   layout out.json             write the rectangles of this frame's widgets and of the
//                               spheres on screen (view/layout_report.h), with the broken rules
//   ui-scale 2                  set the UI scale (as the panel's slider; 0.5 .. 4)
//   quit                        exit now (status 0, or 1 while an error is shown)
//
// Script input goes to the picture, never to the panel.
#pragma once

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace rl {

struct ScriptCommand {
    enum class Kind { Wait, Sleep, WaitReload, Drag, Slide, Scroll, Key, View, Divider, Pick, Resize, Screenshot, Layout, UiScale, Quit };
    Kind kind = Kind::Wait;
    int line = 0;                   // in the script file, for messages
    int count = 0;                  // Wait: frames; Drag: steps; Scroll: steps
    double seconds = 0;             // Sleep, WaitReload
    double value = 0;               // Divider, UiScale; Slide: the end value
    double startValue = 0;          // Slide
    glm::dvec2 from{0.0}, to{0.0};  // Drag; Resize uses `to` as the size, Pick as the pixel
    int button = 0;                 // Drag: 0 left, 1 right, 2 middle (GLFW's numbering)
    std::string text;               // Key: the key name; View: the view name; Screenshot, Layout: the file; Slide: the value
    bool withUi = false;            // Screenshot
};

// Throws rl::Error "script.txt:4: drag needs X0 Y0 X1 Y1" and the like.
std::vector<ScriptCommand> parseScript(const std::string& path);
std::vector<ScriptCommand> parseScriptText(const std::string& text, const std::string& origin);

}  // namespace rl
