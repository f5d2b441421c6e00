// `raylab view`: the live ray tracer in a window. One frame of the loop:
//   events (GLFW callbacks, or the script) -> hot reloads -> the picture
//   (only when something changed, at a lower resolution while moving) ->
//   panel and overlays -> swap.
// Everything runs on this thread except the file watchers, which only raise
// flags. Input handling and actions are in view_app_input.cpp.
#pragma once

#include "camera/trackball.h"
#include "view/caption_layer.h"
#include "gl/context_glfw.h"
#include "render/implementation_facts.h"
#include "view/adaptive_resolution.h"
#include "view/asked_pixel_label.h"
#include "view/file_watcher.h"
#include "view/frame_parts.h"
#include "view/frame_stats.h"
#include "view/gpu_timer.h"
#include "view/imgui_layer.h"
#include "view/live_program.h"
#include "view/layout_report.h"
#include "view/live_scene.h"
#include "view/named_cameras.h"
#include "view/overlays.h"
#include "view/panel.h"
#include "view/script_player.h"
#include "view/split_picture.h"
#include "view/view_options.h"
#include "view/view_state.h"

#include "reference/pixel_breakdown.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rl {

class ViewApp final : private ScriptTarget {
public:
    // Throws rl::Error (one line) for a bad option, scene, folder or script,
    // or when no window can be opened. A shader that does not compile is not
    // an error here: the window opens and shows it.
    explicit ViewApp(const ViewOptions& options);
    ~ViewApp() override;

    // Runs until the window closes, the script quits or --frames are done.
    // Returns the exit status: 0, or 1 when a run with --frames or --script
    // ends with an error on screen.
    int run();

private:
    friend struct ViewAppCallbacks;  // GLFW's C callbacks, in view_app_input.cpp
    using Clock = std::chrono::steady_clock;

    // One implementation: its live program and the watcher of its files.
    struct Side {
        std::unique_ptr<LiveProgram> program;
        std::unique_ptr<FileWatcher> watcher;
        std::optional<ShadingModel> model;  // the model it shows (--compare-model); none: the scene's
        ImplementationFacts facts;          // of its files, at the last build (render/implementation_facts.h)
    };

    // -- the loop (view_app.cpp)
    void frame();
    bool waitOrPoll();  // true: it waited for events (idle)
    // --stats: the GL queue finished at the end of part `p`, so each part is
    // charged with its own pixels (frame_parts.h); without --stats, a mark only.
    void endPart(FrameParts::Part p);
    void applyReloads();
    void rebuild(Side& side, bool initial);
    ShaderDefines liveDefines(const Side& side) const;  // the live program's defines (render/define_table.h)
    // Puts the program for the current view, structure and model in use,
    // compiling it only when it was not built since the sources changed.
    void selectProgram(Side& side);
    void sceneChanged(bool cameraMayHaveChanged);
    void renderPicture(bool fullResolution);
    // The side's picture for `frame` drawn with the course generator's
    // program (issue #25) where it applies and its structure is built; else
    // nullptr, and the side's live program (render/define_table.h) draws it.
    PictureProgram* stillPicture(Side& side);
    void drawUi(ViewRequests& requests, const WipeLabels& wipeLabels);
    void handleRequests(const ViewRequests& requests);
    void writeScreenshot(const std::string& file, bool withUi);
    // Writes the edited scene to state_.savePath; a bundled scene only when `confirmed`.
    void saveScene(bool confirmed = false);
    void openPreset(int index);
    bool moving() const;
    bool stillPending_ = false;  // drawn with the structure's program until the hand stops
    std::vector<std::string> errors() const;
    void toast(const std::string& message);
    void printStats() const;
    int currentPreset() const;
    ViewCaption currentCaption() const;
    std::string windowTitle() const;
    std::vector<OverlaySegment> pickedRays() const;
    std::vector<OverlayLabel> sideBySideLabels() const;  // the two names, clear of the panel  // the asked pixel's rays, projected by the current camera  // "raylab view - SCENE - IMPLEMENTATIONS"
    // The spheres on screen ("sphere N", framebuffer pixels, side by side
    // one per half): the subject the caption, errors and names keep clear of.
    // A sphere the camera is in, or one whose rectangle covers more than a
    // quarter of its picture (the ground, the backdrop), is no subject.
    std::vector<std::pair<std::string, LayoutRect>> subjectRects() const;
    // The panel's rectangle (framebuffer pixels) as last drawn; before it
    // was drawn, where panelRect() puts it. Empty when hidden.
    LayoutRect panelPixels() const;
    void writeLayout(const std::string& file);
    int bounceViewLimit() const;  // max bounces + 1: one past the limit shows black

    // -- input and actions (view_app_input.cpp)
    void installCallbacks();
    // A press from the window system: the panel's, an asked pixel, or the camera's.
    void onPress(int button, int mods, glm::dvec2 pixel);
    void onKey(int key, int action, int mods);
    void onCharacter(unsigned codepoint);  // keys by character (key_bindings.h, byCharacter)
    void onMouseButton(int button, bool pressed, glm::dvec2 pixel, bool fromScript);
    void onCursor(glm::dvec2 pixel);
    void onScroll(double steps);
    void perform(Action action, int argument);
    glm::dvec2 toPixels(glm::dvec2 screen) const;  // window (screen) coordinates to framebuffer pixels
    glm::dvec2 toWindowUnits() const;              // framebuffer pixels -> window units: the factor per axis
    double dividerPixel() const;                   // the wipe divider in framebuffer pixels
    bool wipeActive() const { return sides_.size() == 2 && state_.wipe && !state_.sideBySide; }
    bool sideBySideActive() const { return sides_.size() == 2 && state_.sideBySide; }
    void cameraMoved();
    // A value the picture depends on changed by hand (a slider, a key, a
    // bounce view): the same low-resolution "moving" state as a drag.
    void valueChanged();
    // Ask a pixel: the CPU reference's terms at `pixel` (framebuffer, top-left origin).
    void pickPixel(glm::dvec2 pixel);
    // The pixel debugger's answer for picture pixel (i, j) (row from the
    // bottom) of side `side`'s code; the CPU reference's breakdown alone,
    // with the reason, when the debugger's program does not build.
    std::string debugPickedPixel(int side, const Scene& scene, const Camera& camera, int width, int height, int i, int j);
    // The columns [x0, x0 + width) of the picture `half` shows (side by side), or (half < 0) the
    // picture right of the docked panel (the whole window while it is hidden).
    void pictureColumns(int half, int& x0, int& width) const;
    // Side by side: the rows of the letterboxed half picture (top-left origin).
    void pictureRows(int half, int& y0, int& height) const;
    // Side by side: framebuffer columns left of the pictures (the panel's).
    int sideBySideOffset() const;
    // The framebuffer columns left of the picture: the docked panel's (or
    // its strip's) with a margin while it is shown, 0 while hidden. The
    // picture takes the rest of the window (docs/decisions.md, "The picture
    // beside the panel").
    int pictureOffset() const;
    // tan(fov_y / 2) of the picture over the scene's: the picture beside the
    // panel shows the whole window's width of the scene (its field of view
    // grows upwards and downwards instead of losing the spheres at the sides).
    double fovScale() const;
    // The trackball's camera with the picture's field of view: what the
    // picture, a pick and the projected rays are computed with.
    Camera pictureCamera() const;
    glm::dvec2 trackballPixel(glm::dvec2 pixel) const;  // window pixels -> the picture's, for the trackball

    // ScriptTarget
    void scriptMouseButton(int button, bool pressed, glm::dvec2 pixel) override;
    void scriptCursor(glm::dvec2 pixel) override;
    void scriptScroll(double steps) override;
    void scriptSlide(const std::string& value, double to) override;
    void scriptKey(const KeyBinding& binding) override;
    void scriptView(View view, int bounce) override;
    void scriptDivider(double fraction) override;
    void scriptPick(glm::dvec2 pixel) override;
    void scriptResize(int width, int height) override;
    void scriptScreenshot(const std::string& file, bool withUi) override;
    void scriptLayout(const std::string& file) override { pendingLayout_ = file; }
    void scriptUiScale(double scale) override;
    void scriptQuit() override;
    int reloadCount() const override { return reloads_; }

    // Settings, in the order they are set up (and torn down in reverse: the
    // watchers and GL objects go before the window and its context).
    ViewOptions options_;
    std::optional<ScriptPlayer> script_;
    LiveScene scene_;
    std::vector<std::filesystem::path> presets_;
    std::unique_ptr<GlfwWindowContext> window_;
    std::unique_ptr<ImGuiLayer> ui_;
    std::unique_ptr<CaptionLayer> captions_;
    std::vector<Side> sides_;  // [0] = --impl (left), [1] = --compare (right)
    std::unique_ptr<FileWatcher> sceneWatcher_;
    std::unique_ptr<SplitPicture> picture_;
    std::unique_ptr<GpuTimer> timer_;
    std::unique_ptr<Trackball> trackball_;
    std::unique_ptr<NamedCameras> cameras_;  // F1..F8 (named_cameras.h)

    // State of the running window.
    ViewState state_;
    AdaptiveResolution adaptive_;
    FrameStats stats_;
    FrameParts parts_;  // where each frame's time goes (--stats)
    int fbWidth_ = 0, fbHeight_ = 0;  // framebuffer size this frame
    bool dirty_ = true;               // the picture must be rendered again
    double renderedScale_ = 0;        // scale of the picture on screen; 0 = none yet
    bool softwareRenderer_ = false;   // llvmpipe & co: GL_TIME_ELAPSED misses their threads, so the render is timed by the wall clock
    double lastRenderMs_ = 0;         // the last render's wall time (software renderers only)
    std::vector<double> movingFrameMs_;  // whole frames rendered while moving, for --stats
    std::vector<double> fullRenderMs_;   // renders at full resolution (software renderers), for --stats
    std::vector<double> stillBackMs_;    // from the last move to the swap of the full picture, for --stats
    bool wasMoving_ = false;             // the last rendered frame was a moving one
    int refineBands_ = 0;                // bands drawn, for --stats
    int refineRow_ = 0;                  // a still refining: the next band's first row (from the bottom); 0 = none
    bool refineStill_ = false;           // the refining bands are the still program's
    double refineMsPerRow_ = 0;          // the last band's cost (software renderers), for the next band's rows
    int refineRows_ = 0;                 // RAYLAB_REFINE_ROWS: bands of this many rows (tests: bands at a small size); 0 = by time
    double lowestScale_ = 1.0;        // the lowest scale rendered while moving, for --stats
    Clock::time_point lastMove_{};    // last camera, value or window-size change
    int framesBeforeIdle_ = 0;        // frames to draw before waiting for events
    int framesLeft_ = 0;              // --frames countdown, after the script
    int reloads_ = 0;                 // hot reloads applied (for wait-reload)
    bool quit_ = false;
    bool draggingDivider_ = false;
    bool keyRepeats_ = false;    // the last key event was a repeat: its character is one too
    int dragButton_ = -1;        // the mouse button of the trackball drag, -1 = none
    static constexpr int kMouseButtons = 3;  // left, right, middle (GLFW's numbering)
    bool panelOwnsButton_[kMouseButtons] = {};  // pressed on the panel: everything until the release is the panel's
    glm::dvec2 cursor_{0.0};     // framebuffer pixels, from the last motion event
    std::string runtimeError_;   // a GL error while drawing, shown like a shader error
    std::string pendingShot_;    // picture screenshot to write this frame
    std::string pendingUiShot_;  // window screenshot to write this frame
    std::string pendingLayout_;  // layout report to write this frame
    // The pending screenshot is a script's: no "saved" toast, which would sit
    // in the script's next screenshots (the terminal says it; the panel's status too).
    bool scriptedShot_ = false;
    LayoutReport layout_;        // this frame's rectangles, framebuffer pixels
    PanelRects panelRects_;      // the panel's parts as last drawn, window units
    LayoutRect steadyPanel_;     // the panel, framebuffer pixels, where the last two frames drew it; empty: it moved
    float steadyScale_ = 0;      // the UI scale of the last frame
    int steadyWidth_ = 0, steadyHeight_ = 0;  // the framebuffer size of the last frame
    int quietFrames_ = 0;        // frames since the panel could last have moved, folded or resized
    bool panelSteady_ = false;   // this frame: the picture not presented under the panel; its background cleared
    CaptionLayer::Placement captionPlaced_;  // this frame's caption and names
    LayoutRect errorArea_;                   // where the error box may go this frame, framebuffer pixels
    float errorBoxHeight_ = 0;               // the error box's height last frame, framebuffer pixels
    LayoutRect labelPixels_;                 // the asked pixel's label last frame, framebuffer pixels: the caption keeps clear of it
    std::string status_;         // last save / screenshot, for the panel
    std::string implementationsTitle_;
    int pickedSide_ = 0;   // the code the asked pixel was asked of (0 left / --impl, 1 right)
    int pickedHalf_ = -1;  // side by side: the picture the asked pixel is in (0 left, 1 right); -1 the whole window
    // The pixel debugger's program of each side (render/pixel_debugger.h),
    // built at the first pick after the side's files (rebuild()), program
    // or model changed.
    struct DebugProgram {
        const ShaderProgram* liveProgram = nullptr;  // the side's program it was built beside
        ShaderDefines defines;
        std::unique_ptr<ShaderProgram> program;
    };
    DebugProgram debugPrograms_[2];
    // The asked pixel's answer on the picture (view/asked_pixel_label.h),
    // while the camera is the one it was asked with; lines empty: none.
    AskedPixelLabel askedLabel_;
    Camera askedCamera_;
    std::optional<ref::PixelTerms> picked_;  // the last asked pixel, its rays drawn over the picture  // the implementations' part of the window title
    std::string toast_;
    Clock::time_point toastUntil_{};
};

}  // namespace rl
