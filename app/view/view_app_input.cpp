// ViewApp, part two: mouse, keys and the script, all ending in the same
// handful of functions, and the actions of the key table (key_bindings.h).
#include "view/view_app.h"

#include "render/define_table.h"
#include "render/pixel_debugger.h"

#include "core/error.h"
#include "view/presets.h"
#include "view/screenshot.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace rl {
namespace {

// Exposure keys move half a stop (a factor of sqrt 2): four presses double
// twice, fine enough to find the right brightness live.
const double kHalfStop = std::sqrt(2.0);
// UI scale keys: 25% a press; from 1 to 2 in three presses.
constexpr float kUiScaleStep = 1.25f;
// Wipe keys: 5% of the width a press.
constexpr double kDividerStep = 0.05;
// The divider can be grabbed this many pixels (times the UI scale) either
// side of its line: a 2-pixel line needs a wider target for the mouse.
constexpr double kDividerGrabPixels = 8.0;
// Bounces for "reflections on" when the scene file has none (as presets.cpp).
constexpr int kDefaultBounces = 2;

ViewApp* appOf(GLFWwindow* window) { return static_cast<ViewApp*>(glfwGetWindowUserPointer(window)); }

std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

bool repeats(Action a) {  // actions that a held key repeats; toggles do not
    switch (a) {
        case Action::BounceDown:
        case Action::BounceUp:
        case Action::ExposureDown:
        case Action::ExposureUp:
        case Action::DividerLeft:
        case Action::DividerRight:
        case Action::UiScaleDown:
        case Action::UiScaleUp: return true;
        default: return false;
    }
}

}  // namespace

// GLFW calls plain functions; the window's user pointer leads back here.
// (ImGui's GLFW backend keeps its own state and chains to these.)
struct ViewAppCallbacks {
    static void key(GLFWwindow* w, int key, int, int action, int mods) { appOf(w)->onKey(key, action, mods); }
    static void character(GLFWwindow* w, unsigned codepoint) { appOf(w)->onCharacter(codepoint); }
    // The press happens where the last motion event put the cursor: asking
    // the window system now (glfwGetCursorPos) would give where the mouse is
    // by the time a slow frame lets the events through. It belongs to the
    // panel when that point lies on a window of the last frame drawn (what
    // the user saw under the pointer; ImGui's own hover state is polled at
    // NewFrame and is stale when the pointer has just arrived), and then so
    // does everything up to its release.
    static void button(GLFWwindow* w, int button, int action, int mods) {
        ViewApp* app = appOf(w);
        if (button < 0 || button >= ViewApp::kMouseButtons) return;
        if (action == GLFW_PRESS) {
            app->onPress(button, mods, app->cursor_);
            return;
        }
        if (app->panelOwnsButton_[button]) {  // a press on the panel (or a pick): its release is not the camera's
            app->panelOwnsButton_[button] = false;
            return;
        }
        app->onMouseButton(button, false, app->cursor_, false);
    }
    static void cursor(GLFWwindow* w, double x, double y) {
        ViewApp* app = appOf(w);
        app->cursor_ = app->toPixels({x, y});
        app->onCursor(app->cursor_);
    }
    // The wheel over the panel scrolls the panel, never the camera: ImGui's
    // own flag, or the pointer on a window of the last frame drawn (the
    // flag is polled at NewFrame and is stale when the pointer just arrived).
    static void scroll(GLFWwindow* w, double, double y) {
        ViewApp* app = appOf(w);
        const glm::dvec2 at = app->cursor_ * app->toWindowUnits();
        if (!app->ui_->wantsMouse() && !app->ui_->isOverUi(at.x, at.y)) app->onScroll(y);
    }
};

void ViewApp::onPress(int button, int mods, glm::dvec2 pixel) {
    const glm::dvec2 at = pixel * toWindowUnits();
    if (ui_->isOverUi(at.x, at.y) || ui_->wantsMouse()) {  // the panel's (or a text field's, an open combo's)
        panelOwnsButton_[button] = true;
    } else if (button == GLFW_MOUSE_BUTTON_LEFT && ((mods & GLFW_MOD_CONTROL) || state_.pickMode)) {
        pickPixel(pixel);  // ask the pixel; the camera stays
        panelOwnsButton_[button] = true;
    } else {
        onMouseButton(button, true, pixel, false);
    }
}

void ViewApp::installCallbacks() {
    GLFWwindow* w = window_->window();
    glfwSetWindowUserPointer(w, this);
    glfwSetKeyCallback(w, &ViewAppCallbacks::key);
    glfwSetCharCallback(w, &ViewAppCallbacks::character);
    glfwSetMouseButtonCallback(w, &ViewAppCallbacks::button);
    glfwSetCursorPosCallback(w, &ViewAppCallbacks::cursor);
    glfwSetScrollCallback(w, &ViewAppCallbacks::scroll);
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    cursor_ = toPixels({x, y});
}

glm::dvec2 ViewApp::toPixels(glm::dvec2 screen) const {
    int windowWidth = 1, windowHeight = 1;
    glfwGetWindowSize(window_->window(), &windowWidth, &windowHeight);
    // Screen coordinates to framebuffer pixels (they differ on HiDPI screens).
    return {screen.x * fbWidth_ / std::max(windowWidth, 1), screen.y * fbHeight_ / std::max(windowHeight, 1)};
}

glm::dvec2 ViewApp::toWindowUnits() const {
    int windowWidth = 1, windowHeight = 1;
    glfwGetWindowSize(window_->window(), &windowWidth, &windowHeight);
    return {double(windowWidth) / std::max(fbWidth_, 1), double(windowHeight) / std::max(fbHeight_, 1)};
}

double ViewApp::dividerPixel() const {
    const int x0 = pictureOffset();  // the divider divides the picture, right of the panel
    return x0 + state_.divider * std::max(fbWidth_ - x0, 1);
}

void ViewApp::cameraMoved() {
    lastMove_ = Clock::now();
    dirty_ = true;
}

void ViewApp::valueChanged() {
    // Not a camera move, but the same hand on a control: while values keep
    // changing, each frame renders at the adaptive scale; the full picture
    // comes back kSettleTime after the last change.
    lastMove_ = Clock::now();
    dirty_ = true;
}

void ViewApp::onKey(int key, int action, int mods) {
    if (action == GLFW_RELEASE || ui_->wantsKeyboard()) return;  // typing in a panel field
    auto binding = bindingFor(key, (mods & GLFW_MOD_CONTROL) != 0);
    keyRepeats_ = action == GLFW_REPEAT;  // for the character this key types next (onCharacter)
    if (binding && byCharacter(*binding)) return;  // by the character typed: onCharacter
    if (!binding || (action == GLFW_REPEAT && !repeats(binding->action))) return;
    perform(binding->action, binding->argument);
}

void ViewApp::onCharacter(unsigned codepoint) {
    if (ui_->wantsKeyboard()) return;  // typing in a panel field
    const auto binding = bindingForCharacter(codepoint);
    if (!binding || (keyRepeats_ && !repeats(binding->action))) return;
    perform(binding->action, binding->argument);
}

void ViewApp::onMouseButton(int button, bool pressed, glm::dvec2 pixel, bool fromScript) {
    if (!pressed) {
        if (draggingDivider_ && button == GLFW_MOUSE_BUTTON_LEFT) {
            draggingDivider_ = false;
            dirty_ = true;
        } else if (button == dragButton_) {
            trackball_->drag(trackballPixel(pixel));
            trackball_->endDrag();
            dragButton_ = -1;
            cameraMoved();
        }
        return;
    }
    if ((!fromScript && ui_->wantsMouse()) || dragButton_ >= 0 || draggingDivider_) return;
    if (button == GLFW_MOUSE_BUTTON_LEFT && wipeActive() &&
        std::abs(pixel.x - dividerPixel()) <= kDividerGrabPixels * ui_->scale()) {
        draggingDivider_ = true;
        return;
    }
    Trackball::Mode mode;
    if (button == GLFW_MOUSE_BUTTON_LEFT)
        mode = state_.turntable ? Trackball::Mode::Turntable : Trackball::Mode::Rotate;
    else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE)
        mode = Trackball::Mode::Pan;
    else
        return;
    trackball_->beginDrag(trackballPixel(pixel), mode);
    dragButton_ = button;
    cameraMoved();
}

void ViewApp::onCursor(glm::dvec2 pixel) {
    if (draggingDivider_) {
        const int x0 = pictureOffset();
        state_.divider = std::clamp((pixel.x - x0) / std::max(fbWidth_ - x0, 1), 0.0, 1.0);
        cameraMoved();  // not the camera, but the same "moving" state: low resolution until it stops
    } else if (dragButton_ >= 0) {
        trackball_->drag(trackballPixel(pixel));
        cameraMoved();
    }
}

void ViewApp::pickPixel(glm::dvec2 pixel) {
    // Compared as read, before any conversion (issue 37: 4294967296 wrapped round to 0).
    if (!(pixel.x >= 0 && pixel.y >= 0 && pixel.x < fbWidth_ && pixel.y < fbHeight_)) {
        char where[64];
        std::snprintf(where, sizeof where, "(%.10g, %.10g)", pixel.x, pixel.y);
        std::cerr << "raylab: error: pick " << where << ": outside the " << fbWidth_ << "x"
                  << fbHeight_ << " window (pixels from the top left)" << std::endl;
        return;
    }
    const int i = int(std::floor(pixel.x)), row = int(std::floor(pixel.y));
    if (!sideBySideActive() && i < pictureOffset()) {  // the docked panel's columns: no picture there
        std::cerr << "raylab: error: pick (" << i << ", " << row << "): left of the picture (the panel's columns 0 to "
                  << pictureOffset() - 1 << ")" << std::endl;
        return;
    }
    try {
        Camera camera = pictureCamera();  // the picture's field of view (beside the panel: wider)
        // Side by side, each half is a whole picture of its own width with
        // the same camera: the pixel is asked of the half it is in, in that
        // half's model (--compare-model).
        Scene scene = scene_.scene();
        std::string where;
        pickedHalf_ = -1;
        if (sideBySideActive()) {
            int x1 = 0, w = 0;
            pictureColumns(1, x1, w);
            if (i < sideBySideOffset()) return;  // left of the pictures (the panel's columns)
            pickedHalf_ = i < x1 ? 0 : 1;
            if (sides_[std::size_t(pickedHalf_)].model) scene.model = *sides_[std::size_t(pickedHalf_)].model;
            where = std::string(pickedHalf_ == 0 ? " of the left picture" : " of the right picture") + " (" +
                    sides_[std::size_t(pickedHalf_)].program->label() + ")";
        }
        int x0 = 0, width = fbWidth_, y0 = 0, height = fbHeight_;
        pictureColumns(pickedHalf_, x0, width);
        pictureRows(pickedHalf_, y0, height);
        if (row < y0 || row >= y0 + height) {  // side by side: the bars above and below the pictures
            pickedHalf_ = -1;
            return;
        }
        picked_ = ref::explainPixel(scene, camera, width, height, i - x0, height - 1 - (row - y0));
        // The code on screen at that pixel: side by side the half's, in the
        // wipe the side of the divider it is on.
        int side = pickedHalf_ < 0 ? 0 : pickedHalf_;
        if (wipeActive() && i >= dividerPixel()) side = 1;
        pickedSide_ = side;
        if (wipeActive()) where = std::string(" (") + sides_[std::size_t(side)].program->label() + ", " +
                                  (side == 0 ? "left" : "right") + " of the divider)";
        state_.pickedText = debugPickedPixel(side, scene, camera, width, height, i - x0, height - 1 - (row - y0));
        const glm::dvec2 units = toWindowUnits();  // the label at the pixel's centre, in window units
        askedLabel_.x = float((i + 0.5) * units.x);
        askedLabel_.y = float((row + 0.5) * units.y);
        askedCamera_ = camera;
        state_.pickedSphere = picked_->chain.empty() ? -1 : picked_->chain.front().sphere;
        state_.revealPicked = true;
        std::cout << "raylab: ask a pixel at (" << i - x0 << ", " << row - y0 << ") from the top left" << where << "\n"
                  << state_.pickedText;
        std::cout << "raylab: on the picture:";  // the label's lines, as the window draws them
        for (const std::string& line : askedLabel_.lines) std::cout << " [" << line << "]";
        std::cout << "\n" << std::flush;
    } catch (const Error& e) {
        std::cerr << "raylab: error: " << e.what() << std::endl;
    }
}

std::string ViewApp::debugPickedPixel(int side, const Scene& scene, const Camera& camera, int width, int height, int i,
                                      int j) {
    Side& s = sides_[std::size_t(side)];
    const Implementation& impl = s.program->implementation();
    DebugProgram& debug = debugPrograms_[side];
    try {
        ShaderDefines defines = definesFor(scene, implementationFacts(impl), Purpose::PixelDebug);  // as buildPixelDebugProgram
        if (!debug.program || debug.liveProgram != s.program->program() || debug.defines != defines) {
            debug.program.reset();
            debug.program = std::make_unique<ShaderProgram>(buildPixelDebugProgram(impl, scene));
            debug.liveProgram = s.program->program();
            debug.defines = defines;
        }
        PixelDebug answer = debugPixel(*debug.program, scene, camera, width, height, i, j, s.program->label());
        askedLabel_.lines = pixelDebugLabel(answer);
        askedLabel_.agrees = answer.pixelAgrees || !answer.first();
        if (options_.probeHint) options_.probeHint(answer, impl);
        // Then the reference's whole breakdown (material, l, h, E per light):
        // what the right-hand column was computed from.
        return formatPixelDebug(answer) + "\n" + ref::formatPixelTerms(scene, *picked_);
    } catch (const Error& e) {  // the debugger's program did not build: the reference's terms, and why
        const std::string text = e.what();
        askedLabel_.lines = {"the pixel debugger cannot run this code"};
        askedLabel_.agrees = false;
        return "the pixel debugger cannot run this code (" + text.substr(0, text.find('\n')) +
               "); the CPU reference alone:\n" + ref::formatPixelTerms(scene, *picked_);
    }
}

void ViewApp::pictureColumns(int half, int& x0, int& width) const {
    x0 = 0;
    width = fbWidth_;
    if (half < 0 || !sideBySideActive()) {  // right of the docked panel
        if (sideBySideActive()) return;
        x0 = pictureOffset();
        width = std::max(1, fbWidth_ - x0);
        return;
    }
    // As SplitPicture::renderSideBySide at full resolution.
    const int offset = sideBySideOffset(), split = offset + std::max(1, (fbWidth_ - offset) / 2);
    x0 = half == 0 ? offset : split;
    width = half == 0 ? split - offset : std::max(1, fbWidth_ - split);
}

void ViewApp::pictureRows(int half, int& y0, int& height) const {
    y0 = 0;
    height = fbHeight_;
    if (half < 0 || !sideBySideActive()) return;
    const int offset = sideBySideOffset(), halfWidth = std::max(1, (fbWidth_ - offset) / 2);  // as SplitPicture
    height = std::max(1, int(std::lround(double(fbHeight_) * halfWidth / std::max(fbWidth_, 1))));
    y0 = (fbHeight_ - height) / 2;
}

void ViewApp::onScroll(double steps) {
    trackball_->zoom(steps);
    cameraMoved();
}

void ViewApp::perform(Action action, int argument) {
    RenderSettings& render = scene_.scene().render;
    bool sceneEdited = false;
    switch (action) {
        case Action::ToggleHelp:  // opens at page 1; then the next page; after the last, closes
            if (!state_.showHelp) {
                state_.showHelp = true;
                state_.helpPage = 0;
            } else if (state_.helpPage + 1 < state_.helpPages) {
                ++state_.helpPage;
            } else {
                state_.showHelp = false;
            }
            break;
        case Action::TogglePanel: state_.showPanel = !state_.showPanel; break;
        case Action::ToggleCaptions: state_.showCaptions = !state_.showCaptions; break;
        case Action::TogglePickMode:
            state_.pickMode = !state_.pickMode;
            if (!state_.pickMode) picked_.reset();  // leaving the mode clears the drawn rays
            toast(state_.pickMode ? "pick mode: click a pixel (I leaves)" : "pick mode off");
            break;
        case Action::RecallCamera: {
            const std::string name = "F" + std::to_string(argument);
            const auto camera = cameras_->get(name);
            if (camera && trackball_->setView(*camera)) {
                dragButton_ = -1;
                cameraMoved();
                toast("camera " + name);
            } else {
                toast("no camera " + name + " yet: Ctrl+" + name + " stores the current view");
            }
            break;
        }
        case Action::StoreCamera: {
            const std::string name = "F" + std::to_string(argument);
            try {
                cameras_->set(name, trackball_->camera());
                toast("camera " + name + " stored in " + cameras_->file());
                std::cout << "raylab: camera " << name << " stored in " << cameras_->file() << std::endl;
            } catch (const Error& e) {
                std::cerr << "raylab: error: " << e.what() << std::endl;
                toast(e.what());
            }
            break;
        }
        case Action::ToggleOrbit:
            state_.turntable = !state_.turntable;
            toast(state_.turntable ? "left drag: turntable (no roll)" : "left drag: arcball");
            break;
        case Action::ResetCamera:
            trackball_->reset();
            dirty_ = true;
            break;
        case Action::SetView:  // as a value: the moving picture first, then the full one (in bands for a term view)
            state_.view = View(argument);
            valueChanged();
            break;
        case Action::BounceDown:
        case Action::BounceUp:
            state_.view = View::Bounce;
            state_.viewBounce =
                std::clamp(state_.viewBounce + (action == Action::BounceUp ? 1 : -1), 0, bounceViewLimit());
            toast("view: bounce " + std::to_string(state_.viewBounce) +
                  (state_.viewBounce > render.maxBounces ? " (beyond max bounces: black)" : ""));
            valueChanged();
            break;
        case Action::ExposureDown:
        case Action::ExposureUp:
            render.exposure = std::clamp(render.exposure * (action == Action::ExposureUp ? kHalfStop : 1.0 / kHalfStop),
                                         kMinExposure, kMaxExposure);
            toast("exposure " + formatNumber(render.exposure));
            sceneEdited = true;
            break;
        case Action::CycleGamma:
            if (render.srgb) {
                render.srgb = false;
                render.gamma = 1.0;
                toast("gamma off (1.0)");
            } else if (render.gamma == 1.0) {
                render.gamma = 2.2;
                toast("gamma 2.2");
            } else {
                render.srgb = true;
                toast("gamma sRGB");
            }
            sceneEdited = true;
            break;
        case Action::ToggleReflections: {
            const int fromFile = scene_.fromFile().render.maxBounces;
            render.maxBounces = render.maxBounces > 0 ? 0 : (fromFile > 0 ? fromFile : kDefaultBounces);
            toast(render.maxBounces > 0 ? "reflections on (" + std::to_string(render.maxBounces) + " bounces)"
                                        : "reflections off");
            sceneEdited = true;
            break;
        }
        case Action::PreviousPreset:
        case Action::NextPreset: {
            // The course figures (scenes/presets/, the table of docs/lecture.md)
            // in their order; from any other scene the first (or the last).
            const int n = presetFigureCount(presets_);
            if (n == 0) break;
            const int current = currentPreset() < n ? currentPreset() : -1;
            const int step = action == Action::NextPreset ? 1 : -1;
            openPreset(current < 0 ? (step > 0 ? 0 : n - 1) : (current + step + n) % n);
            break;
        }
        case Action::ToggleCompare:
            if (sides_.size() < 2) {
                toast("no wipe: start with --compare DIR or --compare-model MODEL");
                break;
            }
            if (state_.sideBySide) {  // C in side by side: back to the wipe, which C then toggles
                state_.sideBySide = false;
                state_.wipe = true;
                toast("wipe (C: off, X: side by side)");
            } else {
                state_.wipe = !state_.wipe;
            }
            dirty_ = true;
            break;
        case Action::ToggleSideBySide:
            if (sides_.size() < 2) {
                toast("no side by side: start with --compare DIR or --compare-model MODEL");
                break;
            }
            state_.sideBySide = !state_.sideBySide;
            dirty_ = true;
            break;
        case Action::DividerLeft:
        case Action::DividerRight:
            state_.divider =
                std::clamp(state_.divider + (action == Action::DividerRight ? kDividerStep : -kDividerStep), 0.0, 1.0);
            dirty_ = true;
            break;
        case Action::ToggleFullscreen: window_->toggleFullscreen(); break;
        case Action::Screenshot:
            pendingShot_ = timestampedScreenshotName();
            scriptedShot_ = false;
            break;
        case Action::ScreenshotWithUi:
            pendingUiShot_ = timestampedScreenshotName();
            scriptedShot_ = false;
            break;
        case Action::UiScaleDown: ui_->setScale(ui_->scale() / kUiScaleStep); break;
        case Action::UiScaleUp: ui_->setScale(ui_->scale() * kUiScaleStep); break;
        case Action::SaveScene: saveScene(); break;
        case Action::Escape:
            if (window_->fullscreen())
                window_->toggleFullscreen();
            else
                state_.showHelp = false;
            break;
        case Action::Quit: quit_ = true; break;
    }
    if (sceneEdited) {
        picture_->setScene(scene_.scene());
        valueChanged();  // exposure, gamma, reflections: low resolution while the keys are pressed
    }
}

// Script input goes to the picture directly (never to the panel).
void ViewApp::scriptMouseButton(int button, bool pressed, glm::dvec2 pixel) {
    onMouseButton(button, pressed, pixel, true);
}
void ViewApp::scriptCursor(glm::dvec2 pixel) { onCursor(pixel); }
void ViewApp::scriptScroll(double steps) { onScroll(steps); }
void ViewApp::scriptSlide(const std::string& value, double to) {
    // What the panel's slider does to the scene (panel.cpp), then what
    // handleRequests does with a panel edit.
    Scene& scene = scene_.scene();
    if (value == "exposure") scene.render.exposure = std::clamp(to, kMinExposure, kMaxExposure);
    if (scene.environment) {  // the Environment section's sliders (uniforms: no recompile)
        if (value == "env-intensity") scene.environment->intensity = std::clamp(to, 0.0, kMaxEnvironmentIntensity);
        if (value == "env-rotation") scene.environment->rotationDegrees = to;
    }
    if (!scene.spheres.empty()) {  // the first sphere's slider in the panel's Materials
        Material& m = scene.spheres[0].material;
        if (value == "roughness") m.roughness = std::clamp(to, 0.0, 1.0);
        if (value == "metallic") m.metallic = std::clamp(to, 0.0, 1.0);
    }
    ViewRequests edit;
    edit.sceneEdited = true;
    handleRequests(edit);
}
void ViewApp::scriptKey(const KeyBinding& binding) { perform(binding.action, binding.argument); }
void ViewApp::scriptView(View view, int bounce) {
    state_.view = view;
    if (view == View::Bounce) state_.viewBounce = bounce;
    dirty_ = true;
}
void ViewApp::scriptDivider(double fraction) {
    state_.divider = fraction;
    dirty_ = true;
}
void ViewApp::scriptPick(glm::dvec2 pixel) { pickPixel(pixel); }
void ViewApp::scriptResize(int width, int height) { glfwSetWindowSize(window_->window(), width, height); }
void ViewApp::scriptUiScale(double scale) { ui_->setScale(float(scale)); }
void ViewApp::scriptScreenshot(const std::string& file, bool withUi) {
    (withUi ? pendingUiShot_ : pendingShot_) = file;
    scriptedShot_ = true;
}
void ViewApp::scriptQuit() { quit_ = true; }

}  // namespace rl
