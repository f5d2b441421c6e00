// Every key and mouse action of the live view, in one table: the window's
// input handling dispatches through it, the help overlay (H) lists it, and
// docs/lecture.md repeats it. A key added here is documented everywhere.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rl {

enum class Action {
    ToggleHelp,
    TogglePanel,
    ToggleCaptions,  // the caption and colour bar drawn on the picture
    ToggleOrbit,     // left drag: arcball <-> turntable (no roll)
    TogglePickMode,  // a left click asks the pixel (Ctrl+click always does)
    RecallCamera,    // argument: 1..8, the named camera F1..F8
    StoreCamera,     // argument: 1..8
    ResetCamera,
    SetView,     // argument: the view number 0..10 (rl::View)
    BounceDown,  // the k of view 9 (bounce k)
    BounceUp,
    ExposureDown,
    ExposureUp,
    CycleGamma,         // off (1.0) -> 2.2 -> sRGB
    ToggleReflections,  // max bounces 0 <-> the scene's
    PreviousPreset,
    NextPreset,
    ToggleCompare,  // the wipe, when --compare is given
    ToggleSideBySide,  // two full pictures side by side, when --compare is given
    DividerLeft,
    DividerRight,
    ToggleFullscreen,
    Screenshot,        // the picture only
    ScreenshotWithUi,  // the whole window, panel included
    UiScaleDown,
    UiScaleUp,
    SaveScene,
    Escape,  // leave fullscreen, else close the help
    Quit,
};

struct KeyBinding {
    int key;    // GLFW_KEY_...
    bool ctrl;  // needs Ctrl (Cmd is not used: one binding per platform)
    Action action;
    int argument;      // for SetView
    const char* keys;  // as shown to the user, "1".."9", "Ctrl+S"
    const char* what;  // one line for the help overlay; empty: listed under another key
};

struct MouseBinding {
    const char* input;  // "left drag"
    const char* what;
};

const std::vector<KeyBinding>& keyBindings();
const std::vector<MouseBinding>& mouseBindings();

// The binding for a pressed key (keypad digits count as digits).
std::optional<KeyBinding> bindingFor(int glfwKey, bool ctrl);

// For scripts: "R", "6", "F11", "Ctrl+S", "Up", "PageDown", "Escape", ...
// Throws rl::Error naming the valid names when unknown.
KeyBinding bindingByName(const std::string& name);

}  // namespace rl
