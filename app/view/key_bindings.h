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

// Keys the help names by a character ("+", "]", "Y", "9") are bound to the
// character typed, not to the key's place on a US keyboard: on a German
// layout "+" has a key of its own (where a US "]" is) and "]" is AltGr+9,
// and Y and Z trade places. The window takes them from GLFW's character
// callback; byCharacter() says which bindings those are, and the key
// callback leaves them alone (unless Ctrl is held: no character then).
bool byCharacter(const KeyBinding& binding);
// The binding for a typed character (Unicode code point): a letter in
// either case, "=" for "+" (it shares the key on US layouts) and "_" for "-".
std::optional<KeyBinding> bindingForCharacter(unsigned codepoint);

// For scripts: "R", "6", "F11", "Ctrl+S", "Up", "PageDown", "Escape", ...
// Throws rl::Error naming the valid names when unknown.
KeyBinding bindingByName(const std::string& name);

}  // namespace rl
