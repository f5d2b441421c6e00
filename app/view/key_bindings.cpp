#include "view/key_bindings.h"

#include "core/error.h"
#include "core/message.h"

#include <cctype>

#define GLFW_INCLUDE_NONE  // key codes only
#include <GLFW/glfw3.h>

namespace rl {

const std::vector<KeyBinding>& keyBindings() {
    static const std::vector<KeyBinding> table = {
        {GLFW_KEY_H, false, Action::ToggleHelp, 0, "H", "show this help; again: its next page, after the last: hide it"},
        {GLFW_KEY_TAB, false, Action::TogglePanel, 0, "Tab", "show / hide the panel (a clean picture to project)"},
        {GLFW_KEY_K, false, Action::ToggleCaptions, 0, "K", "caption and colour bar on the picture on / off"},
        {GLFW_KEY_I, false, Action::TogglePickMode, 0, "I", "pick mode: a click asks the pixel (Ctrl+click always does)"},
        {GLFW_KEY_T, false, Action::ToggleOrbit, 0, "T", "left drag: arcball / turntable (horizon stays level)"},
        {GLFW_KEY_F1, false, Action::RecallCamera, 1, "F1", "recall named camera F1 (SCENE.cameras.json)"},
        {GLFW_KEY_F1, true, Action::StoreCamera, 1, "Ctrl+F1", "store the current view as named camera F1"},
        {GLFW_KEY_F2, false, Action::RecallCamera, 2, "F2", "recall named camera F2 (SCENE.cameras.json)"},
        {GLFW_KEY_F2, true, Action::StoreCamera, 2, "Ctrl+F2", "store the current view as named camera F2"},
        {GLFW_KEY_F3, false, Action::RecallCamera, 3, "F3", "recall named camera F3 (SCENE.cameras.json)"},
        {GLFW_KEY_F3, true, Action::StoreCamera, 3, "Ctrl+F3", "store the current view as named camera F3"},
        {GLFW_KEY_F4, false, Action::RecallCamera, 4, "F4", "recall named camera F4 (SCENE.cameras.json)"},
        {GLFW_KEY_F4, true, Action::StoreCamera, 4, "Ctrl+F4", "store the current view as named camera F4"},
        {GLFW_KEY_F5, false, Action::RecallCamera, 5, "F5", "recall named camera F5 (SCENE.cameras.json)"},
        {GLFW_KEY_F5, true, Action::StoreCamera, 5, "Ctrl+F5", "store the current view as named camera F5"},
        {GLFW_KEY_F6, false, Action::RecallCamera, 6, "F6", "recall named camera F6 (SCENE.cameras.json)"},
        {GLFW_KEY_F6, true, Action::StoreCamera, 6, "Ctrl+F6", "store the current view as named camera F6"},
        {GLFW_KEY_F7, false, Action::RecallCamera, 7, "F7", "recall named camera F7 (SCENE.cameras.json)"},
        {GLFW_KEY_F7, true, Action::StoreCamera, 7, "Ctrl+F7", "store the current view as named camera F7"},
        {GLFW_KEY_F8, false, Action::RecallCamera, 8, "F8", "recall named camera F8 (SCENE.cameras.json)"},
        {GLFW_KEY_F8, true, Action::StoreCamera, 8, "Ctrl+F8", "store the current view as named camera F8"},
        {GLFW_KEY_R, false, Action::ResetCamera, 0, "R", "reset the camera to the scene file's"},
        {GLFW_KEY_0, false, Action::SetView, 0, "0", "view: final picture"},
        {GLFW_KEY_1, false, Action::SetView, 1, "1", "view: D, normal distribution (key light)"},
        {GLFW_KEY_2, false, Action::SetView, 2, "2", "view: G, geometry term (key light)"},
        {GLFW_KEY_3, false, Action::SetView, 3, "3", "view: F(v.h), Fresnel of the key light's highlight"},
        {GLFW_KEY_4, false, Action::SetView, 4, "4", "view: diffuse radiance of all lights"},
        {GLFW_KEY_5, false, Action::SetView, 5, "5", "view: specular radiance of all lights"},
        {GLFW_KEY_6, false, Action::SetView, 6, "6", "view: n.l of the key light"},
        {GLFW_KEY_7, false, Action::SetView, 7, "7", "view: shadow of the key light"},
        {GLFW_KEY_8, false, Action::SetView, 8, "8", "view: normals"},
        {GLFW_KEY_9, false, Action::SetView, 9, "9", "view: bounce k alone"},
        {GLFW_KEY_V, false, Action::SetView, 10, "V", "view: F(n.v), reflection weight of the bounces (rims)"},
        {GLFW_KEY_E, false, Action::SetView, 11, "E", "view: environment irradiance E(n) / pi (SH9)"},
        {GLFW_KEY_L, false, Action::SetView, 12, "L", "view: prefiltered environment towards r (specular)"},
        {GLFW_KEY_Y, false, Action::SetView, 13, "Y", "view: split-sum scale at (n.v, roughness)"},
        {GLFW_KEY_U, false, Action::SetView, 14, "U", "view: split-sum bias at (n.v, roughness)"},
        {GLFW_KEY_LEFT_BRACKET, false, Action::BounceDown, 0, "[", "bounce k - 1 (view 9)"},
        {GLFW_KEY_RIGHT_BRACKET, false, Action::BounceUp, 0, "]", "bounce k + 1 (view 9; up to max bounces + 1, which is black)"},
        {GLFW_KEY_DOWN, false, Action::ExposureDown, 0, "Down", "exposure half a stop down"},
        {GLFW_KEY_UP, false, Action::ExposureUp, 0, "Up", "exposure half a stop up"},
        {GLFW_KEY_G, false, Action::CycleGamma, 0, "G", "gamma: off (1.0) -> 2.2 -> sRGB"},
        {GLFW_KEY_B, false, Action::ToggleReflections, 0, "B", "reflections off / on (max bounces 0 / the scene's)"},
        {GLFW_KEY_PAGE_UP, false, Action::PreviousPreset, 0, "PageUp", "previous preset scene"},
        {GLFW_KEY_PAGE_DOWN, false, Action::NextPreset, 0, "PageDown", "next preset scene (the course figures, scenes/presets/, in order)"},
        {GLFW_KEY_C, false, Action::ToggleCompare, 0, "C", "split-screen wipe on / off (--compare, --compare-model); in side by side: the wipe"},
        {GLFW_KEY_X, false, Action::ToggleSideBySide, 0, "X", "side by side on / off: two full pictures (--compare, --compare-model)"},
        {GLFW_KEY_LEFT, false, Action::DividerLeft, 0, "Left", "move the wipe divider left"},
        {GLFW_KEY_RIGHT, false, Action::DividerRight, 0, "Right", "move the wipe divider right"},
        {GLFW_KEY_F11, false, Action::ToggleFullscreen, 0, "F11", "fullscreen on / off"},
        {GLFW_KEY_F, false, Action::ToggleFullscreen, 0, "F", "fullscreen on / off"},
        {GLFW_KEY_P, false, Action::Screenshot, 0, "P", "screenshot of the picture (raylab-DATE-TIME.png)"},
        {GLFW_KEY_F12, false, Action::ScreenshotWithUi, 0, "F12", "screenshot of the whole window, panel included"},
        {GLFW_KEY_MINUS, false, Action::UiScaleDown, 0, "-", "smaller panel and text"},
        {GLFW_KEY_EQUAL, false, Action::UiScaleUp, 0, "+", "larger panel and text (projectors)"},
        {GLFW_KEY_S, true, Action::SaveScene, 0, "Ctrl+S", "save the edited scene (as in the panel)"},
        {GLFW_KEY_ESCAPE, false, Action::Escape, 0, "Escape", "leave fullscreen / close the help"},
        {GLFW_KEY_Q, false, Action::Quit, 0, "Q", "quit"},
    };
    return table;
}

const std::vector<MouseBinding>& mouseBindings() {
    static const std::vector<MouseBinding> table = {
        {"left drag", "rotate about the target (arcball; T: turntable, no roll)"},
        {"right / middle drag", "pan"},
        {"Ctrl+click", "ask the pixel: its terms from the CPU reference, its rays drawn"},
        {"wheel", "zoom towards / away from the target"},
        {"left drag on the divider", "move the wipe (--compare, --compare-model)"},
    };
    return table;
}

namespace {
// Keypad keys do what the main keys do.
int canonicalKey(int key) {
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) return GLFW_KEY_0 + (key - GLFW_KEY_KP_0);
    if (key == GLFW_KEY_KP_ADD) return GLFW_KEY_EQUAL;
    if (key == GLFW_KEY_KP_SUBTRACT) return GLFW_KEY_MINUS;
    return key;
}
}  // namespace

std::optional<KeyBinding> bindingFor(int glfwKey, bool ctrl) {
    const int key = canonicalKey(glfwKey);
    for (const KeyBinding& b : keyBindings())
        if (b.key == key && b.ctrl == ctrl) return b;
    return std::nullopt;
}

bool byCharacter(const KeyBinding& b) {
    const std::string keys = b.keys;
    return !b.ctrl && keys.size() == 1 && std::isprint(static_cast<unsigned char>(keys[0]));
}

std::optional<KeyBinding> bindingForCharacter(unsigned codepoint) {
    if (codepoint > 127) return std::nullopt;
    char c = char(std::toupper(int(codepoint)));
    if (c == '=') c = '+';
    if (c == '_') c = '-';
    for (const KeyBinding& b : keyBindings())
        if (byCharacter(b) && b.keys[0] == c) return b;
    return std::nullopt;
}

KeyBinding bindingByName(const std::string& name) {
    std::string valid;
    for (const KeyBinding& b : keyBindings()) {
        std::string keys = b.keys;
        if (keys == name || (keys.size() == 1 && name.size() == 1 && std::toupper(keys[0]) == std::toupper(name[0])))
            return b;
        valid += (valid.empty() ? "" : ", ") + keys;
    }
    throw Error("unknown key " + quotedValue(name) + " (expected one of " + valid + ")");
}

}  // namespace rl
