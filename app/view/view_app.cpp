#include "view/view_app.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/message.h"
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "course/exercise_registry.h"
#include "render/define_table.h"
#include "view/implementation_folder.h"
#include "view/input_script.h"
#include "view/overlays.h"
#include "view/panel.h"
#include "view/presets.h"
#include "view/scene_patch.h"
#include "view/screenshot.h"

#define GLFW_INCLUDE_NONE  // gl_api.h declares the GL functions
#include <GLFW/glfw3.h>

#include <imgui.h>  // the panel's background colour

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace rl {
namespace {

std::string readTextFile(const std::string& path) { return readRegularFile(path, kMaxTextFileBytes, "the scene file"); }

// After the camera's last change, keep the low resolution this long before
// refining: mouse-wheel notches and drag events arrive every 10-50 ms, and
// refining between two of them would make every other frame a slow one.
// 120 ms, not 200 (issue 37): the still comes in bands of 100 ms, so a pause
// mistaken for the end costs one band, not a whole blocking still, and the
// full picture is back 80 ms sooner.
constexpr auto kSettleTime = std::chrono::milliseconds(120);
// Idle: wait for events at most this long (the file watchers wake the loop
// at once; the time-out only refreshes the panel's clock-driven parts).
constexpr double kIdleWaitSeconds = 0.5;
// Frames drawn after any wake-up before waiting again: ImGui needs one or
// two frames to settle hover and layout after an input event.
constexpr int kFramesAfterWake = 3;
// A still refines in bands of about this long each (one a frame): the
// window answers input 10 times a second while the full picture comes in.
constexpr double kRefineBandMs = 100.0;
constexpr int kMinRefineRows = 8;
// How long a toast ("saved ...") stays on screen.
constexpr auto kToastTime = std::chrono::seconds(3);

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up && a.fovYDegrees == b.fovYDegrees;
}

std::string sceneName(const std::string& path) {
    return path.empty() ? "default scene" : fs::path(path).filename().string();
}

}  // namespace

ViewApp::ViewApp(const ViewOptions& options) : options_(options), scene_(options.scene) {
    for (const auto& w : scene_.warnings()) std::cerr << "raylab: warning: " << w << "\n";
    if (!options_.script.empty()) script_.emplace(parseScript(options_.script), options_.script);
    int bounce = 0;
    state_.view = parseView(options_.view, bounce);
    if (state_.view == View::Bounce) state_.viewBounce = bounce;

    std::vector<Implementation> impls;
    impls.push_back(implementationFrom(options_.impl.empty() ? defaultImplementationDir() : fs::path(options_.impl), "--impl"));
    if (!options_.compare.empty()) impls.push_back(implementationFrom(options_.compare, "--compare"));
    std::optional<ShadingModel> compareModel;
    std::string compareModelName;
    if (options_.compareModel == "blinn-phong") {
        compareModel = ShadingModel{};
        compareModel->blinnPhong = true;
        compareModelName = "Blinn-Phong";
    } else if (options_.compareModel == "pbr") {
        compareModel = ShadingModel{};  // the reference model: GGX, Schlick-GGX, Schlick, Lambert
        compareModelName = "PBR";
    } else if (!options_.compareModel.empty()) {
        throw Error("--compare-model: unknown model " + quotedValue(options_.compareModel) + " (expected blinn-phong or pbr)");
    }
    if (compareModel && impls.size() == 1) impls.push_back(impls[0]);  // the same code, another model
    if (options_.sideBySide && impls.size() < 2)  // an option that does not apply: refused, not ignored
        throw Error("--side-by-side: needs a second picture (--compare DIR or --compare-model MODEL)");

    WindowSettings settings;
    settings.width = options_.width > 0 ? options_.width : scene_.scene().render.width;
    settings.height = options_.height > 0 ? options_.height : scene_.scene().render.height;
    implementationsTitle_ = implementationLabel(impls[0]) + (impls.size() > 1 ? " | " + implementationLabel(impls[1]) : "");
    settings.title = windowTitle();
    settings.vsync = options_.frames == 0;  // timing runs measure the renderer, not the display
    window_ = std::make_unique<GlfwWindowContext>(settings);
    window_->framebufferSize(fbWidth_, fbHeight_);
    installCallbacks();  // before ImGui, which chains to them
    ui_ = std::make_unique<ImGuiLayer>(window_->window());
    float contentScale = 1.0f;
#ifndef __APPLE__
    // X11 and Windows report HiDPI as a content scale and give ImGui pixels;
    // macOS scales ImGui's coordinates itself.
    glfwGetWindowContentScale(window_->window(), &contentScale, nullptr);
#endif
    ui_->setScale(options_.uiScale > 0 ? options_.uiScale : contentScale);
    captions_ = std::make_unique<CaptionLayer>();

    picture_ = std::make_unique<SplitPicture>();
    timer_ = std::make_unique<GpuTimer>();
    if (const GLubyte* name = gl::GetString(GL_RENDERER)) {
        const std::string renderer = reinterpret_cast<const char*>(name);
        for (const char* software : {"llvmpipe", "softpipe", "SwiftShader"})
            softwareRenderer_ = softwareRenderer_ || renderer.find(software) != std::string::npos;
    }
    for (std::size_t i = 0; i < impls.size(); ++i) {
        Side side;
        std::string label = implementationLabel(impls[i]);
        if (compareModel) {  // name the model on both sides
            const ShadingModel& own = scene_.scene().model;
            if (i == 1) side.model = compareModel;
            label += ", " + (i == 1              ? compareModelName
                             : own.blinnPhong    ? "Blinn-Phong"
                             : own.isReference() ? "PBR"
                                                 : "the scene's model");
        }
        side.program = std::make_unique<LiveProgram>(impls[i], label);
        side.watcher = std::make_unique<FileWatcher>([] { glfwPostEmptyEvent(); });
        sides_.push_back(std::move(side));
        rebuild(sides_.back(), true);
    }
    if (!scene_.path().empty()) {
        sceneWatcher_ = std::make_unique<FileWatcher>([] { glfwPostEmptyEvent(); });
        sceneWatcher_->watch({scene_.path()});
    }
    picture_->setScene(scene_.scene());
    trackball_ = std::make_unique<Trackball>(scene_.scene().camera, std::max(fbWidth_, 1), std::max(fbHeight_, 1));

    presets_ = presetScenes();
    cameras_ = std::make_unique<NamedCameras>(namedCamerasFile(scene_.path()));
    if (!cameras_->error().empty()) std::cerr << "raylab: warning: " << cameras_->error() << "\n";
    state_.wipe = sides_.size() == 2;
    state_.savePath = defaultSavePath(scene_.path());  // never the course file itself
    state_.showPanel = !options_.hidePanel;
    state_.panelStrip = options_.panelStrip;
    state_.showCaptions = !options_.hideCaptions;
    state_.sideBySide = options_.sideBySide && sides_.size() == 2;
    if (const char* rows = std::getenv("RAYLAB_REFINE_ROWS")) refineRows_ = std::max(0, std::atoi(rows));
    framesLeft_ = options_.frames;
    if (options_.frames > 0) state_.continuous = true;  // every frame renders: the median is the renderer's
    if (options_.fullscreen) window_->toggleFullscreen();
}

ViewApp::~ViewApp() = default;

int ViewApp::run() {
    while (!quit_ && !glfwWindowShouldClose(window_->window())) frame();
    if (options_.stats || options_.frames > 0) printStats();
    const bool scripted = options_.frames > 0 || script_;
    if (scripted && !errors().empty()) {
        std::cerr << "raylab: error: the run ended with an error on screen (see above)\n";
        return 1;
    }
    return 0;
}

void ViewApp::endPart(FrameParts::Part p) {
    if (options_.stats && parts_.profiled() && p != FrameParts::Events && p != FrameParts::Programs &&
        p != FrameParts::UiBuild)
        gl::Finish();
    parts_.mark(p);
}

void ViewApp::frame() {
    parts_.begin();
    if (waitOrPoll()) parts_.begin();  // idle time is no frame time
    const auto frameStart = Clock::now();  // after the wait: idle time is no frame time
    const bool scriptDone = !script_ || script_->finished();
    if (!scriptDone) script_->step(*this);
    endPart(FrameParts::Events);
    applyReloads();
    for (Side& side : sides_) selectProgram(side);  // the view may have changed: its program
    endPart(FrameParts::Programs);

    int width = 0, height = 0;
    window_->framebufferSize(width, height);
    if (width != fbWidth_ || height != fbHeight_) {
        fbWidth_ = width;
        fbHeight_ = height;
        lastMove_ = Clock::now();  // resizing counts as moving: low resolution until it stops
        dirty_ = true;
    }
    if (fbWidth_ <= 0 || fbHeight_ <= 0) return;  // minimised: nothing to draw
    trackball_->setViewport(sideBySideActive() ? fbWidth_ : std::max(1, fbWidth_ - pictureOffset()), fbHeight_);
    adaptive_.enabled = state_.adaptiveResolution;
    while (auto result = timer_->poll()) {
        stats_.addGpu(result->ms);
        adaptive_.record(result->ms, result->tag);
    }

    const bool lastFrame = scriptDone && framesLeft_ == 1;
    if (lastFrame && !options_.screenshot.empty()) pendingShot_ = options_.screenshot;
    const bool screenshot = !pendingShot_.empty() || !pendingUiShot_.empty();
    const bool refine = !moving() && (renderedScale_ < 1.0 || stillPending_ || refineRow_ > 0);
    bool rendered = false;
    if (dirty_ || state_.continuous || refine || (screenshot && (renderedScale_ < 1.0 || refineRow_ > 0))) {
        renderPicture(screenshot);
        rendered = true;
    }
    endPart(FrameParts::Render);
    // The opaque panel's pixels are not presented (on llvmpipe every window
    // pixel drawn costs; issue 37) where it stays where it was drawn the
    // last two frames and no hand moves it; the picture's own screenshot
    // needs them all.
    const LayoutRect panelNow = panelPixels();
    // Anything that may move, fold or resize the panel this frame (a hand on
    // it or over it, a new window size or UI scale, the help taking the
    // window) starts the count again: two quiet frames first.
    const bool touched = panelOwnsButton_[0] || panelOwnsButton_[1] || panelOwnsButton_[2] || ui_->wantsMouse() ||
                         state_.showHelp || steadyScale_ != ui_->scale() || steadyWidth_ != fbWidth_ ||
                         steadyHeight_ != fbHeight_;
    quietFrames_ = touched ? 0 : quietFrames_ + 1;
    steadyWidth_ = fbWidth_, steadyHeight_ = fbHeight_;
    const bool panelSteady = !panelNow.empty() && panelNow.x0 == steadyPanel_.x0 && panelNow.y0 == steadyPanel_.y0 &&
                             panelNow.x1 == steadyPanel_.x1 && panelNow.y1 == steadyPanel_.y1 && quietFrames_ >= 2 &&
                             pendingShot_.empty() && !panelRects_.panel.empty();
    const int covered[4] = {int(std::ceil(panelNow.x0)), int(std::ceil(panelNow.y0)), int(std::floor(panelNow.x1)),
                            int(std::floor(panelNow.y1))};
    picture_->present(fbWidth_, fbHeight_, panelSteady ? covered : nullptr, pictureOffset());
    panelSteady_ = panelSteady;
    endPart(FrameParts::Present);
    const std::vector<OverlaySegment> rays = pickedRays();
    const std::vector<OverlayLabel> labels = sideBySideLabels();
    // What the caption keeps clear of: the spheres, the panel, the wipe's names.
    layout_ = LayoutReport{fbWidth_, fbHeight_, ui_->scale(), {}};
    {  // where the picture is: the docked panel stays clear of it
        int x0 = 0, width = 0, y0 = 0, rows = 0;
        pictureColumns(sideBySideActive() ? 0 : -1, x0, width);
        pictureRows(sideBySideActive() ? 0 : -1, y0, rows);
        layout_.add("picture", LayoutBox::Kind::Picture, {float(x0), float(y0), float(fbWidth_), float(y0 + rows)});
    }
    std::vector<LayoutRect> avoid;
    for (const auto& [name, rect] : subjectRects()) {
        layout_.add(name, LayoutBox::Kind::Subject, rect);
        avoid.push_back(rect);
    }
    const LayoutRect panel = panelPixels();
    if (!panel.empty()) avoid.push_back(panel);
    // The columns left of the picture (the panel's and its margin): the
    // caption stays on the picture, whole in its screenshot.
    if (const int x0 = sideBySideActive() ? 0 : pictureOffset(); x0 > 0) avoid.push_back({0, 0, float(x0), float(fbHeight_)});
    // The asked pixel's answer, where it was last frame (it is placed after
    // the caption, clear of it; beside the docked panel the picture is
    // narrower, and without this the two could find no room apart).
    if (!labelPixels_.empty()) avoid.push_back(labelPixels_);
    float topReserved = 0;
    WipeLabels wipeLabels;
    const glm::dvec2 perUnit = 1.0 / toWindowUnits();  // framebuffer pixels per window unit
    if (wipeActive()) {  // placed before the caption, which stays below them
        const float s = ui_->scale(), fontSize = 13 * s;  // ImGui's default font at the UI scale (window units)
        wipeLabels = wipeLabelBoxes(float(dividerPixel() / perUnit.x), float(fbWidth_ / perUnit.x),
                                    state_.showPanel ? panel.x1 / float(perUnit.x) : 0.0f,
                                    captions_->textWidth(sides_[0].program->label(), fontSize),
                                    captions_->textWidth(sides_[1].program->label(), fontSize), fontSize, s);
        topReserved = std::max(wipeLabels.left.y1, wipeLabels.right.y1) * float(perUnit.y);
    }
    // The errors come first: the tallest band of rows right of the panel
    // that neither the spheres nor the names take; the caption keeps clear
    // of the box's part of it, and yields where it then finds no room.
    errorArea_ = {};
    const bool showErrors = !errors().empty();
    if (showErrors) {
        const float margin = 10 * ui_->scale() * float(perUnit.x);
        std::vector<LayoutRect> taken = avoid;  // the spheres (and the panel, left of the band anyway)
        if (wipeActive()) {
            taken.push_back({0, 0, float(fbWidth_), topReserved});
        } else if (sideBySideActive()) {  // the names in the bar above the pictures
            int y0 = 0, rows = 0;
            pictureRows(0, y0, rows);
            taken.push_back({0, 0, float(fbWidth_), float(y0)});
        }
        const float x0 = panel.empty() ? margin : panel.x1 + margin, x1 = float(fbWidth_) - margin;
        std::vector<std::pair<float, float>> blocked;
        for (const LayoutRect& t : taken)
            if (t.x0 < x1 && x0 < t.x1) blocked.push_back({t.y0 - margin, t.y1 + margin});
        std::sort(blocked.begin(), blocked.end());
        float y = margin;
        auto consider = [&](float y0, float y1) {
            if (y1 - y0 > errorArea_.y1 - errorArea_.y0) errorArea_ = {x0, y0, x1, y1};
        };
        for (const auto& [b0, b1] : blocked) {
            if (b0 > y) consider(y, b0);
            y = std::max(y, b1);
        }
        if (float(fbHeight_) - margin > y) consider(y, float(fbHeight_) - margin);
        // Less than two lines: the whole window (the error matters more than what it covers).
        if (errorArea_.y1 - errorArea_.y0 < 2 * 13 * ui_->scale() * float(perUnit.y) || x1 - x0 < 10 * 13 * ui_->scale() * float(perUnit.x))
            errorArea_ = {margin, margin, float(fbWidth_) - margin, float(fbHeight_) - margin};
        const float height = errorBoxHeight_ > 0 ? std::min(errorBoxHeight_, errorArea_.y1 - errorArea_.y0)
                                                 : errorArea_.y1 - errorArea_.y0;
        avoid.push_back({errorArea_.x0, errorArea_.y1 - height, errorArea_.x1, errorArea_.y1});
    }
    captionPlaced_ = {};
    if (state_.showCaptions || !rays.empty() || !labels.empty())
        captionPlaced_ = captions_->draw(currentCaption(), state_.showCaptions, rays, labels, fbWidth_, fbHeight_,
                                         ui_->scale(), avoid, topReserved, showErrors);
    endPart(FrameParts::Overlays);
    if (!pendingShot_.empty()) writeScreenshot(pendingShot_, false);
    pendingShot_.clear();

    ViewRequests requests;
    drawUi(requests, wipeLabels);
    if (!pendingUiShot_.empty()) writeScreenshot(pendingUiShot_, true);
    pendingUiShot_.clear();
    if (!pendingLayout_.empty()) writeLayout(pendingLayout_);
    pendingLayout_.clear();
    endPart(FrameParts::UiDraw);
    steadyPanel_ = panelNow.x0 == panelPixels().x0 && panelNow.y0 == panelPixels().y0 &&
                           panelNow.x1 == panelPixels().x1 && panelNow.y1 == panelPixels().y1
                       ? panelNow
                       : LayoutRect{};
    steadyScale_ = ui_->scale();
    glfwSwapBuffers(window_->window());
    endPart(FrameParts::Swap);
    if (rendered) {
        const bool movingFrame = renderedScale_ < 1.0 || moving() || refineRow_ > 0;
        parts_.end(movingFrame);
        // The full picture back: from the hand's last move to this swap.
        if (!movingFrame && wasMoving_)
            stillBackMs_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - lastMove_).count());
        wasMoving_ = movingFrame;
    }
    if (rendered) {
        const double frameMs = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
        stats_.addWall(frameMs);
        if (renderedScale_ < 1.0 || moving()) {  // the frames a drag is made of
            movingFrameMs_.push_back(frameMs);
            lowestScale_ = std::min(lowestScale_, renderedScale_);
            if (softwareRenderer_) adaptive_.recordFrame(frameMs, lastRenderMs_);
        }
    }

    handleRequests(requests);
    if (scriptDone && framesLeft_ > 0 && --framesLeft_ == 0) quit_ = true;
}

bool ViewApp::waitOrPoll() {
    if (fbWidth_ <= 0 || fbHeight_ <= 0) {  // minimised: nothing to draw until the window comes back
        glfwWaitEventsTimeout(kIdleWaitSeconds);
        return true;
    }
    const bool busy = dirty_ || state_.continuous || moving() || renderedScale_ < 1.0 || refineRow_ > 0 || framesBeforeIdle_ > 0 ||
                      (script_ && !script_->finished()) || framesLeft_ > 0 || Clock::now() < toastUntil_;
    if (busy) {
        glfwPollEvents();
        if (framesBeforeIdle_ > 0) --framesBeforeIdle_;
        return false;
    }
    glfwWaitEventsTimeout(kIdleWaitSeconds);
    framesBeforeIdle_ = kFramesAfterWake;
    return true;
}

void ViewApp::applyReloads() {
    for (Side& side : sides_)
        if (side.watcher->takeChange()) rebuild(side, false);
    if (sceneWatcher_ && sceneWatcher_->takeChange()) {
        const Camera before = scene_.fromFile().camera;
        ++reloads_;
        if (scene_.reload()) {
            for (const auto& w : scene_.warnings()) std::cerr << "raylab: warning: " << w << "\n";
            std::cout << "raylab: reloaded " << scene_.path() << std::endl;
            sceneChanged(!sameCamera(before, scene_.fromFile().camera));
        } else {
            std::cerr << "raylab: error: " << scene_.error() << " (the last good scene stays on screen)" << std::endl;
        }
    }
}

void ViewApp::rebuild(Side& side, bool initial) {
    LiveProgram& program = *side.program;
    side.facts = implementationFacts(program.implementation());
    program.setDefines(liveDefines(side));
    const bool ok = program.rebuild();
    // The files changed: the pixel debugger's program of this side is built
    // again at the next pick (a freed program's address may come back).
    debugPrograms_[&side - sides_.data()].program.reset();
    side.watcher->watch(program.files());
    if (!initial) ++reloads_;
    if (ok) {
        if (!initial)
            std::cout << "raylab: reloaded " << program.label() << " (" << int(std::lround(program.lastBuildMs()))
                      << " ms)" << std::endl;
        stats_.clearRecent();
        dirty_ = true;
    } else {
        std::cerr << "raylab: " << program.label() << ": the shader does not build"
                  << (program.program() ? "; the last good picture stays on screen" : "") << ":\n"
                  << program.error() << std::endl;
    }
}

ShaderDefines ViewApp::liveDefines(const Side& side) const {
    // Specialised to the scene's structure, never to its values
    // (Purpose::LiveView, render/define_table.h): a slider re-uploads
    // uniforms only; another sphere count, bounce limit, model or view kind
    // selects another program. The term views draw with the generic
    // program: with the structure's unrolled loops they were slower, not
    // faster (0.56x to 0.67x of the generic one at 1280x720), and their
    // first draw (llvmpipe's JIT) 4x longer (docs/performance.md).
    const Purpose purpose = options_.generic || !isPictureView(state_.view) ? Purpose::Generic : Purpose::LiveView;
    if (!side.model) return definesFor(scene_.scene(), side.facts, purpose);
    Scene shown = scene_.scene();  // --compare-model: this side's model
    shown.model = *side.model;
    return definesFor(shown, side.facts, purpose);
}

void ViewApp::selectProgram(Side& side) {
    LiveProgram& program = *side.program;
    const ShaderProgram* before = program.program();
    if (program.setDefines(liveDefines(side))) {
        const bool ok = program.build();
        side.watcher->watch(program.files());
        if (ok) {
            std::cout << "raylab: built " << program.label() << " for " << viewName(state_.view, state_.viewBounce)
                      << " (" << int(std::lround(program.lastBuildMs())) << " ms, " << program.keptPrograms()
                      << " kept)" << std::endl;
        } else {
            std::cerr << "raylab: " << program.label() << ": the shader does not build"
                      << (program.program() ? "; the last good picture stays on screen" : "") << ":\n"
                      << program.error() << std::endl;
        }
    }
    if (program.program() != before) {
        stats_.clearRecent();
        dirty_ = true;
    }
}

void ViewApp::sceneChanged(bool cameraChanged) {
    for (Side& side : sides_) selectProgram(side);  // another structure or model: another program
    picture_->setScene(scene_.scene());
    if (cameraChanged)
        trackball_ = std::make_unique<Trackball>(scene_.scene().camera, std::max(fbWidth_, 1), std::max(fbHeight_, 1));
    state_.viewBounce = std::clamp(state_.viewBounce, 0, bounceViewLimit());
    dirty_ = true;
}

PictureProgram* ViewApp::stillPicture(Side& side) {
    LiveProgram& program = *side.program;
    // The whole frame of one side, the picture or a bounce view: the same
    // path as `raylab render` for whatever files are shown, with the scene's
    // values compiled in (Purpose::LiveStill); a slider that moves changes
    // them, and the structure's program draws until the hand stops
    // (docs/decisions.md, "One program").
    if (options_.generic || !isPictureView(state_.view) || sides_.size() > 1 || !program.error().empty() || !program.program())
        return nullptr;
    Scene shown = scene_.scene();
    if (side.model) shown.model = *side.model;
    bool built = false;
    PictureProgram* still = program.still(definesFor(shown, side.facts, Purpose::LiveStill), !moving(), built);
    if (built)
        std::cout << "raylab: built " << program.label() << " for the still picture, the scene's numbers compiled in ("
                  << int(std::lround(program.lastBuildMs())) << " ms)" << std::endl;
    if (!still) stillPending_ = true;
    return still;
}

bool ViewApp::moving() const { return dragButton_ >= 0 || draggingDivider_ || Clock::now() - lastMove_ < kSettleTime; }

void ViewApp::renderPicture(bool fullResolution) {
    const bool stillWasPending = stillPending_;  // the last picture: the structure's program at full size
    // Right of the docked panel (the whole window side by side: its halves
    // leave the panel's columns themselves).
    const int pictureWidth = sideBySideActive() ? fbWidth_ : std::max(1, fbWidth_ - pictureOffset());
    const double scale = fullResolution ? 1.0 : adaptive_.scale(moving(), pictureWidth, fbHeight_);
    stillPending_ = false;
    FrameSettings frame = frameFromScene(scene_.scene());
    frame.cameraToWorld = trackball_->cameraToWorldD();
    frame.fovYRadians = 2.0 * std::atan(std::tan(0.5 * frame.fovYRadians) * fovScale());
    frame.width = std::max(1, int(std::lround(pictureWidth * scale)));
    frame.height = std::max(1, int(std::lround(fbHeight_ * scale)));
    frame.view = state_.view;
    frame.viewBounce = state_.viewBounce;
    frame.radiance = false;  // the window shows the display target; the radiance is never read here
    const int split = wipeActive() ? int(std::lround(state_.divider * frame.width)) : frame.width;
    PictureProgram* still = stillPicture(sides_[0]);
    const ShaderProgram* left = sides_[0].program->program();
    const ShaderProgram* right = sides_.size() > 1 ? sides_[1].program->program() : nullptr;
    // Every still (a term view's generic program, the picture's still
    // program with its sky tiles: up to seconds at 1080p on llvmpipe) in
    // bands of rows, one a frame, over the upscaled moving picture, so the
    // window keeps answering while it refines (issue 37). The first band
    // after a change starts at row 0; a move starts over, and so does
    // another program.
    const bool progressive = scale == 1.0 && !fullResolution && !sideBySideActive() && renderedScale_ > 0 &&
                             (renderedScale_ < 1.0 || refineRow_ > 0 || (stillWasPending && still));
    int band0 = 0, band1 = frame.height;
    if (progressive) {
        if (refineRow_ > 0 && refineStill_ != (still != nullptr)) refineRow_ = 0;
        if (refineRow_ == 0) refineMsPerRow_ = 0;  // a new still: the moving frames' estimate first
        const double msPerRow = refineMsPerRow_ > 0 ? refineMsPerRow_ : adaptive_.msPerPixel() * frame.width;
        const int rows = refineRows_ > 0 ? refineRows_ : msPerRow > 0 ? int(kRefineBandMs / msPerRow) : frame.height / 8;
        band0 = refineRow_;
        band1 = refineRows_ > 0 ? std::min(frame.height, band0 + rows)
                                : std::min(frame.height, (band0 + std::max(rows, kMinRefineRows) + 15) / 16 * 16);  // llvmpipe's 16-row tiles whole
        refineStill_ = still != nullptr;
        // Over the full-size picture of the structure's program: it stays on
        // screen under the bands (the reduced one is the upscale source already).
        if (band0 == 0 && renderedScale_ >= 1.0) picture_->keepForRefining();
    }
    const double pixels = double(frame.width) * (band1 - band0);
    const auto renderStart = Clock::now();
    if (!softwareRenderer_) timer_->begin(pixels);
    try {
        if (still)  // the whole frame (or its band): with its sky tiles
            picture_->render(*still, frame, !moving(), band0, band1);
        else if (sideBySideActive())
            picture_->renderSideBySide(left, right, frame, double(sideBySideOffset()) / std::max(fbWidth_, 1));
        else
            picture_->render(left, right, frame, split, band0, band1);
        runtimeError_.clear();
    } catch (const Error& e) {
        if (runtimeError_ != e.what()) std::cerr << "raylab: error: " << e.what() << std::endl;
        runtimeError_ = e.what();
    }
    if (softwareRenderer_) {
        // llvmpipe renders on its worker threads when the draw is flushed;
        // glFinish here costs nothing the swap would not wait for anyway.
        gl::Finish();
        lastRenderMs_ = std::chrono::duration<double, std::milli>(Clock::now() - renderStart).count();
        stats_.addGpu(lastRenderMs_);
        adaptive_.record(lastRenderMs_, pixels);
        if (scale == 1.0 && !progressive) fullRenderMs_.push_back(lastRenderMs_);
        if (progressive && band1 > band0) refineMsPerRow_ = lastRenderMs_ / (band1 - band0);
    } else {
        timer_->end();
    }
    if (progressive) ++refineBands_;
    refineRow_ = progressive && band1 < frame.height ? band1 : 0;
    picture_->setRefinedRows(progressive && band1 < frame.height ? band1 : -1);
    renderedScale_ = scale;
    dirty_ = false;
}

void ViewApp::drawUi(ViewRequests& requests, const WipeLabels& wipeLabels) {
    ui_->beginFrame();
    const float scale = ui_->scale();
    PanelInfo info;
    const GLubyte* renderer = gl::GetString(GL_RENDERER);
    info.device = renderer ? reinterpret_cast<const char*>(renderer) : "";
    info.scenePath = scene_.path();
    info.left = sides_[0].program->label();
    if (sides_.size() > 1) info.right = sides_[1].program->label();
    info.gpuMs = stats_.recentGpuMs();
    info.frameMs = stats_.recentWallMs();
    info.renderWidth = picture_->width();
    info.renderHeight = picture_->height();
    info.windowWidth = fbWidth_;
    info.windowHeight = fbHeight_;
    info.presets = &presets_;
    info.currentPreset = currentPreset();
    info.uiScale = scale;
    info.status = status_;
    info.backgroundCleared = panelSteady_;
    if (state_.showHelp)  // the help has the window (below); the panel comes back when it closes
        panelRects_ = {};
    else
        requests = drawPanel(scene_.scene(), scene_.fromFile(), state_, info, &panelRects_);
    // The help over the whole window, opaque, at the UI scale, in pages;
    // the panel steps aside while it is open (drawPanel: it would be under
    // it anyway), so none of the panel's text shows through or beside it.
    const HelpRects help = drawHelpOverlay(state_.showHelp, state_.helpPage, state_.helpPages, scale);

    // Window units from here (ImGui's); the report in framebuffer pixels.
    const glm::dvec2 perUnit = 1.0 / toWindowUnits();
    auto toUnits = [&](LayoutRect r) {
        return LayoutRect{float(r.x0 / perUnit.x), float(r.y0 / perUnit.y), float(r.x1 / perUnit.x), float(r.y1 / perUnit.y)};
    };
    auto toPixels = [&](LayoutRect r) {
        return LayoutRect{float(r.x0 * perUnit.x), float(r.y0 * perUnit.y), float(r.x1 * perUnit.x), float(r.y1 * perUnit.y)};
    };
    const float windowHeight = float(fbHeight_ / perUnit.y);

    if (!help.box.empty()) {
        layout_.add("help", LayoutBox::Kind::Cover, toPixels(help.box));
        layout_.add("help rows", LayoutBox::Kind::Part, toPixels(help.rows), "help");
    }
    const LayoutRect errorBox = drawErrorOverlay(errors(), scale, toUnits(errorArea_));
    errorBoxHeight_ = (errorBox.y1 - errorBox.y0) * float(perUnit.y);
    if (!errorBox.empty()) layout_.add("errors", LayoutBox::Kind::Widget, toPixels(errorBox));

    // The toast ("saved ..."), for 3 s: right of the panel, below the wipe's
    // names (and the caption when it went to the top); clear of the
    // overlays, but it may cover spheres for those seconds.
    LayoutRect toastBox;
    // While an error box is shown, no toast: the error has the room (the
    // toast's message is in the terminal and the panel's status).
    if (Clock::now() < toastUntil_ && errorBox.empty()) {
        float top = wipeActive() ? std::max(wipeLabels.left.y1, wipeLabels.right.y1) + 10 * scale : 0.0f;
        for (const LayoutRect& l : captionPlaced_.labels) top = std::max(top, toUnits(l).y1 + 10 * scale);
        if (!captionPlaced_.box.empty() && captionPlaced_.box.y0 < 0.5f * fbHeight_)
            top = std::max(top, toUnits(captionPlaced_.box).y1 + 10 * scale);
        const float left = panelRects_.panel.empty() ? 0.0f : panelRects_.panel.x1;
        toastBox = drawToast(toast_, scale, top, float(fbWidth_ / perUnit.x) - left - 20 * scale);
        if (!toastBox.empty()) layout_.add("toast", LayoutBox::Kind::Tool, toPixels(toastBox));
    }
    // The asked pixel's answer beside it, clear of the widgets; the divider
    // goes around it (view/asked_pixel_label.h). The help, while open, has
    // the window: the label comes back when it closes.
    LayoutRect labelBox;
    if (!askedLabel_.lines.empty() && sameCamera(askedCamera_, pictureCamera()) && !state_.showHelp) {
        std::vector<LayoutRect> avoid = {errorBox, panelRects_.panel, toastBox};
        if (wipeActive()) avoid.insert(avoid.end(), {wipeLabels.left, wipeLabels.right});
        if (!captionPlaced_.box.empty()) avoid.push_back(toUnits(captionPlaced_.box));
        for (const LayoutRect& l : captionPlaced_.labels) avoid.push_back(toUnits(l));
        labelBox = drawAskedPixelLabel(askedLabel_, scale, avoid);
        layout_.add("asked pixel label", LayoutBox::Kind::Tool, toPixels(labelBox));
    }
    const LayoutRect labelBefore = labelPixels_;
    labelPixels_ = labelBox.empty() ? LayoutRect{} : toPixels(labelBox);
    if (labelBefore.x0 != labelPixels_.x0 || labelBefore.y0 != labelPixels_.y0 || labelBefore.x1 != labelPixels_.x1 ||
        labelBefore.y1 != labelPixels_.y1)
        framesBeforeIdle_ = std::max(framesBeforeIdle_, 2);  // the caption moves aside next frame
    if (wipeActive()) {
        std::vector<LayoutRect> clear = {wipeLabels.left, wipeLabels.right, errorBox, panelRects_.panel, toastBox, labelBox};
        if (!captionPlaced_.box.empty()) clear.push_back(toUnits(captionPlaced_.box));
        const std::vector<LayoutRect> divider =
            dividerPieces(float(dividerPixel() / perUnit.x), windowHeight, scale, clear);
        drawWipeOverlay(divider, wipeLabels, sides_[0].program->label(), sides_[1].program->label(), scale);
        for (const LayoutRect& piece : divider) layout_.add("divider", LayoutBox::Kind::Line, toPixels(piece));
        layout_.add("wipe left name", LayoutBox::Kind::Widget, toPixels(wipeLabels.left));
        layout_.add("wipe right name", LayoutBox::Kind::Widget, toPixels(wipeLabels.right));
    }
    endPart(FrameParts::UiBuild);
    if (panelSteady_ && !panelRects_.panel.empty()) {  // the panel's background, as a clear (PanelInfo::backgroundCleared)
        const LayoutRect r = toPixels(panelRects_.panel);
        const int x0 = int(std::floor(r.x0)), x1 = int(std::ceil(r.x1)), y0 = int(std::floor(r.y0)), y1 = int(std::ceil(r.y1));
        const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        gl::Enable(GL_SCISSOR_TEST);
        gl::Scissor(x0, fbHeight_ - y1, x1 - x0, y1 - y0);
        gl::ClearColor(bg.x, bg.y, bg.z, 1.0f);
        gl::Clear(GL_COLOR_BUFFER_BIT);
        gl::Disable(GL_SCISSOR_TEST);
    }
    ui_->endFrame();

    if (!captionPlaced_.box.empty()) {
        layout_.add("caption", LayoutBox::Kind::Widget, captionPlaced_.box);
        layout_.add("colour bar", LayoutBox::Kind::Part, captionPlaced_.bar, "caption");
    }
    for (std::size_t i = 0; i < captionPlaced_.labels.size(); ++i)
        layout_.add(i == 0 ? "left name" : "right name", LayoutBox::Kind::Widget, captionPlaced_.labels[i]);
    const PanelRects& p = panelRects_;
    if (!p.panel.empty()) {
        layout_.add("panel", LayoutBox::Kind::Dock, toPixels(p.panel));
        if (!p.titleBar.empty()) {
            layout_.add("panel title bar", LayoutBox::Kind::Part, toPixels(p.titleBar), "panel");
            layout_.add("panel title", LayoutBox::Kind::Part, toPixels(p.title), "panel title bar");
        }
        if (!p.viewCombo.empty()) {
            layout_.add("view dropdown", LayoutBox::Kind::Part, toPixels(p.viewCombo), "panel");
            layout_.add("view name", LayoutBox::Kind::Part, toPixels(p.viewText), "view dropdown");
        }
        if (!p.askedPixel.empty()) layout_.add("asked pixel", LayoutBox::Kind::Part, toPixels(p.askedPixel), "panel");
        if (!p.content.empty()) {
            layout_.add("panel content", LayoutBox::Kind::Part, toPixels(p.content), "panel");
            layout_.add("panel rows", LayoutBox::Kind::Part, toPixels(p.rows), "panel content");
        }
    }
}

LayoutRect ViewApp::panelPixels() const {
    if (!state_.showPanel) return {};
    const glm::dvec2 perUnit = 1.0 / toWindowUnits();
    LayoutRect r = panelRects_.panel;
    if (r.empty() && !state_.panelStrip) {  // not drawn yet: where it will be
        const PanelRect p = panelRect(float(fbWidth_ / perUnit.x), float(fbHeight_ / perUnit.y), ui_->scale());
        r = {p.x, p.y, p.x + p.width, p.y + p.height};
    }
    return {float(r.x0 * perUnit.x), float(r.y0 * perUnit.y), float(r.x1 * perUnit.x), float(r.y1 * perUnit.y)};
}

std::vector<std::pair<std::string, LayoutRect>> ViewApp::subjectRects() const {
    std::vector<std::pair<std::string, LayoutRect>> out;
    if (fbWidth_ <= 0 || fbHeight_ <= 0) return out;
    const Scene& scene = scene_.scene();
    const Camera camera = trackball_->camera();
    const glm::dvec3 f = glm::normalize(camera.target - camera.position);
    const glm::dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const glm::dvec3 u = glm::cross(r, f);
    const double tanHalf = std::tan(0.5 * glm::radians(scene.camera.fovYDegrees)) * fovScale();
    const int halves = sideBySideActive() ? 2 : 1;
    for (int half = 0; half < halves; ++half) {
        int x0 = 0, width = fbWidth_, y0 = 0, height = fbHeight_;
        pictureColumns(sideBySideActive() ? half : -1, x0, width);
        pictureRows(sideBySideActive() ? half : -1, y0, height);
        const double aspect = double(width) / std::max(height, 1);
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            const glm::dvec3 c = scene.spheres[i].center - camera.position;
            const double radius = scene.spheres[i].radius, d = glm::length(c);
            if (d <= radius * 1.0001) continue;  // the camera is inside it
            // The silhouette: a circle of radius rho about q, across the line of sight.
            const glm::dvec3 w = c / d;
            const glm::dvec3 q = w * (d - radius * radius / d);
            const double rho = radius * std::sqrt(d * d - radius * radius) / d;
            const glm::dvec3 a = glm::normalize(std::abs(w.x) < 0.9 ? glm::cross(w, glm::dvec3(1, 0, 0))
                                                                     : glm::cross(w, glm::dvec3(0, 1, 0)));
            const glm::dvec3 b = glm::cross(w, a);
            double minX = 1e30, minY = 1e30, maxX = -1e30, maxY = -1e30;
            bool behind = false;
            constexpr int kSamples = 90;  // 4 degrees apart: the box is short by at most 0.25% of the radius
            for (int k = 0; k < kSamples && !behind; ++k) {
                const double t = 2 * M_PI * k / kSamples;
                const glm::dvec3 p = q + rho * (std::cos(t) * a + std::sin(t) * b);
                const double z = glm::dot(p, f);
                if (z <= 1e-6) {
                    behind = true;  // wraps round the camera: a backdrop
                    break;
                }
                const double x = x0 + (glm::dot(p, r) / (z * tanHalf * aspect) + 1.0) * 0.5 * width;
                const double y = y0 + (1.0 - glm::dot(p, u) / (z * tanHalf)) * 0.5 * height;
                minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
            }
            if (behind) continue;
            const LayoutRect box{float(std::max<double>(minX, x0)), float(std::max<double>(minY, y0)),
                                 float(std::min<double>(maxX, x0 + width)), float(std::min<double>(maxY, y0 + height))};
            if (box.empty()) continue;  // off the picture
            if ((maxX - minX) * (maxY - minY) > 0.25 * double(width) * height) continue;  // the ground, a backdrop
            out.push_back({"sphere " + std::to_string(i) + (halves == 2 ? (half == 0 ? " left" : " right") : ""), box});
        }
    }
    return out;
}

void ViewApp::writeLayout(const std::string& file) {
    try {
        writeFileAtomic(file, layoutJson(layout_), WriteOptions{"the layout report"});
        const std::vector<std::string> problems = layoutProblems(layout_);
        std::cout << "raylab: layout " << fs::absolute(file).lexically_normal().string() << " (" << problems.size()
                  << " problem" << (problems.size() == 1 ? "" : "s") << ")" << std::endl;
        for (const std::string& p : problems) std::cout << "raylab: layout: " << p << "\n";
    } catch (const Error& e) {
        std::cerr << "raylab: error: " << e.what() << std::endl;
    }
}

void ViewApp::handleRequests(const ViewRequests& r) {
    // Values re-upload uniforms only; a new model (the one structural edit
    // of the panel) also compiles that model's program.
    if (r.sceneEdited) {
        sceneChanged(false);
        valueChanged();  // a slider being dragged: low resolution until the hand stops
    }
    if (r.redraw) dirty_ = true;
    if (r.openPreset >= 0) openPreset(r.openPreset);
    if (r.save || r.saveConfirmed) saveScene(r.saveConfirmed);
    if (r.resetCamera) perform(Action::ResetCamera, 0);
    if (r.screenshot) perform(Action::Screenshot, 0);
    if (r.screenshotWithUi) perform(Action::ScreenshotWithUi, 0);
    if (r.uiScale > 0) ui_->setScale(r.uiScale);
}

void ViewApp::writeScreenshot(const std::string& file, bool withUi) {
    try {
        DisplayImage shot = readWindowPixels(fbWidth_, fbHeight_);
        // The picture's screenshot is the picture (right of the docked
        // panel), the window's the whole window (docs/decisions.md).
        if (const int x0 = sideBySideActive() ? 0 : pictureOffset(); !withUi && x0 > 0 && x0 < shot.width) {
            DisplayImage picture{shot.width - x0, shot.height, std::vector<std::uint8_t>(std::size_t(shot.width - x0) * shot.height * 3)};
            for (int y = 0; y < shot.height; ++y)
                for (int x = x0; x < shot.width; ++x)
                    for (int c = 0; c < 3; ++c) picture.at(x - x0, y)[c] = shot.at(x, y)[c];
            shot = std::move(picture);
        }
        writePng(file, shot);
        const std::string shown = fs::absolute(file).lexically_normal().string();
        std::cout << "raylab: screenshot " << shown << (withUi ? " (window)" : "") << std::endl;
        status_ = "saved " + shown;
        if (!scriptedShot_) toast("saved " + file);
    } catch (const Error& e) {
        std::cerr << "raylab: error: " << e.what() << std::endl;
        status_ = e.what();
        toast(e.what());
    }
}

void ViewApp::saveScene(bool confirmed) {
    const std::string target = state_.savePath;
    if (isBundledScene(target) && !confirmed) {  // a course file: only after "overwrite" in the panel
        state_.askOverwrite = true;
        state_.showPanel = true;
        status_ = target + " is a bundled scene: confirm in the panel, or save as another file";
        std::cout << "raylab: " << status_ << std::endl;
        toast(status_);
        return;
    }
    Scene scene = scene_.scene();
    // The camera only when it moved: an untouched trackball rebuilds the
    // file's camera from its quaternion (up orthonormalised), which is not
    // a change the lecturer made.
    const Camera fileCamera = scene_.fromFile().camera;
    const bool moved = !sameCamera(trackball_->camera(), Trackball(fileCamera, 1, 1).camera());
    scene.camera = state_.saveCamera && moved ? trackball_->camera() : fileCamera;
    try {
        std::string text;
        if (!scene_.path().empty()) {  // the file's own text, changed values patched in place
            const std::string original = readTextFile(scene_.path());
            try {
                text = patchSceneText(original, parseScene(original, scene_.path()).scene, scene);
            } catch (const Error& e) {  // not patchable (edited elsewhere into something else): written whole
                std::cerr << "raylab: warning: " << scene_.path() << ": " << e.what() << "; the scene is written whole"
                          << std::endl;
                text.clear();
            }
        }
        // Atomic (core/file_io.h): the file watcher (and any editor) never
        // sees a half-written scene.
        if (text.empty())
            saveSceneFile(scene, target);
        else
            writeFileAtomic(target, text, WriteOptions{"the scene file"});
        state_.askOverwrite = false;
        status_ = "saved " + target + (moved && state_.saveCamera ? " (with the moved camera)" : "");
        std::cout << "raylab: " << status_ << std::endl;
    } catch (const Error& e) {
        status_ = e.what();
        std::cerr << "raylab: error: " << e.what() << std::endl;
    }
    toast(status_);
}

void ViewApp::openPreset(int index) {
    if (index < 0 || index >= int(presets_.size())) return;
    const std::string path = presets_[std::size_t(index)].string();
    if (!scene_.open(path)) {
        std::cerr << "raylab: error: " << scene_.error() << std::endl;
        toast(scene_.error());
        return;
    }
    if (!sceneWatcher_) sceneWatcher_ = std::make_unique<FileWatcher>([] { glfwPostEmptyEvent(); });
    sceneWatcher_->watch({path});
    state_.savePath = defaultSavePath(path);
    cameras_ = std::make_unique<NamedCameras>(namedCamerasFile(path));
    picked_.reset();  // another scene: the asked pixel's spheres are gone
    askedLabel_.lines.clear();
    state_.pickedText.clear();
    state_.pickedSphere = -1;
    glfwSetWindowTitle(window_->window(), windowTitle().c_str());  // the title names the scene on screen
    sceneChanged(true);
    toast(presetTitle(presets_[std::size_t(index)]));
}

ViewCaption ViewApp::currentCaption() const {
    const Scene& scene = scene_.scene();
    ViewCaption c = viewCaption(state_.view, state_.viewBounce, scene, sides_[0].model.value_or(scene.model));
    if ((wipeActive() || sideBySideActive()) && sides_[1].model) {  // --compare-model: name both sides' models
        const std::string right = viewCaption(state_.view, state_.viewBounce, scene, *sides_[1].model).model;
        if (right != c.model) c.model = "left: " + c.model + "  |  right: " + right;
    }
    return c;
}

std::vector<OverlaySegment> ViewApp::pickedRays() const {
    std::vector<OverlaySegment> out;
    if (!picked_ || fbWidth_ <= 0 || fbHeight_ <= 0) return out;
    const Scene& scene = scene_.scene();
    const Camera camera = trackball_->camera();
    const glm::dvec3 f = glm::normalize(camera.target - camera.position);
    const glm::dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const glm::dvec3 u = glm::cross(r, f);
    const double tanHalf = std::tan(0.5 * glm::radians(scene.camera.fovYDegrees)) * fovScale();
    // Side by side: the half the pixel was asked in; asked in the wipe or
    // the whole window before X, the half of the code it was asked of
    // (issue 37: the rays stayed at their full-window places, across the names).
    const int half = sideBySideActive() ? (pickedHalf_ >= 0 ? pickedHalf_ : pickedSide_) : -1;
    int x0 = 0, width = fbWidth_;
    pictureColumns(half, x0, width);
    int y0 = 0, height = fbHeight_;
    pictureRows(half, y0, height);
    const double aspect = double(width) / height;
    // Points closer than this along the view direction are clipped away:
    // a ray from the camera itself projects to no point.
    const double nearPlane = 1e-3 * glm::length(camera.target - camera.position);
    auto segment = [&](glm::dvec3 a, glm::dvec3 b, unsigned colour) {
        glm::dvec3 ca(glm::dot(a - camera.position, r), glm::dot(a - camera.position, u), glm::dot(a - camera.position, f));
        glm::dvec3 cb(glm::dot(b - camera.position, r), glm::dot(b - camera.position, u), glm::dot(b - camera.position, f));
        if (ca.z < nearPlane && cb.z < nearPlane) return;
        if (ca.z < nearPlane) ca += (cb - ca) * ((nearPlane - ca.z) / (cb.z - ca.z));
        if (cb.z < nearPlane) cb += (ca - cb) * ((nearPlane - cb.z) / (ca.z - cb.z));
        auto toPixel = [&](glm::dvec3 c) {
            return glm::dvec2(x0 + (c.x / (c.z * tanHalf * aspect) + 1.0) * 0.5 * width,
                              y0 + (1.0 - c.y / (c.z * tanHalf)) * 0.5 * height);
        };
        glm::dvec2 pa = toPixel(ca), pb = toPixel(cb);
        // Clipped to the picture (Liang-Barsky): side by side, a ray never
        // leaves its half for the bars and the names above it.
        double t0 = 0, t1 = 1;
        const glm::dvec2 d = pb - pa;
        const double p[4] = {-d.x, d.x, -d.y, d.y};
        const double q[4] = {pa.x - x0, x0 + width - pa.x, pa.y - y0, y0 + height - pa.y};
        for (int k = 0; k < 4; ++k) {
            if (p[k] == 0) {
                if (q[k] < 0) return;  // parallel to this edge and outside it
                continue;
            }
            const double t = q[k] / p[k];
            if (p[k] < 0) t0 = std::max(t0, t);
            else t1 = std::min(t1, t);
        }
        if (t0 > t1) return;
        const glm::dvec2 from = pa + t0 * d, to = pa + t1 * d;
        out.push_back({float(from.x), float(from.y), float(to.x), float(to.y), colour});
    };
    // Colours: primary and reflected rays yellow / cyan, shadow rays green
    // when the light is visible, red when a sphere blocks it.
    const unsigned kPrimary = 0xFF40E0FFu, kReflected = 0xFFFFE040u, kLit = 0xFF40FF60u, kShadowed = 0xFF4040FFu;
    for (const ref::BounceTerms& b : picked_->chain) {
        const unsigned colour = b.depth == 0 ? kPrimary : kReflected;
        if (!b.hit) {  // leaves the scene: as long as the camera's distance to its target
            segment(b.origin, b.origin + b.dir * glm::length(camera.target - camera.position), colour);
            continue;
        }
        segment(b.origin, b.p, colour);
        for (const ref::LightTerms& l : b.lights)
            if (!l.facesAway) segment(b.p, scene.lights[std::size_t(l.light)].position, l.shadowed ? kShadowed : kLit);
    }
    return out;
}

std::vector<OverlayLabel> ViewApp::sideBySideLabels() const {
    if (!sideBySideActive()) return {};
    const float s = ui_->scale(), margin = 10 * s;
    int x0 = 0, width = 0, x1 = 0;
    pictureColumns(0, x0, width);
    pictureColumns(1, x1, width);
    // Each name wraps inside its own half (issue 26: at UI scale 3 on
    // 1280x720 the two ran into each other).
    const float wrap = std::max(1.0f, float(width) - 2 * margin);
    return {{float(x0) + margin, margin, sides_[0].program->label(), wrap},
            {float(x1) + margin, margin, sides_[1].program->label(), wrap}};
}

std::string ViewApp::windowTitle() const {
    return "raylab view - " + sceneName(scene_.path()) + " - " + implementationsTitle_;
}

int ViewApp::sideBySideOffset() const { return sideBySideActive() ? pictureOffset() : 0; }

double ViewApp::fovScale() const {
    if (sideBySideActive()) return 1.0;  // each half is the whole window's picture, letterboxed
    const int offset = pictureOffset();
    return double(std::max(fbWidth_, 1)) / std::max(fbWidth_ - offset, 1);
}

Camera ViewApp::pictureCamera() const {
    Camera camera = trackball_->camera();
    const double tanHalf = std::tan(0.5 * glm::radians(scene_.scene().camera.fovYDegrees)) * fovScale();
    camera.fovYDegrees = glm::degrees(2.0 * std::atan(tanHalf));
    return camera;
}

glm::dvec2 ViewApp::trackballPixel(glm::dvec2 pixel) const {
    return sideBySideActive() ? pixel : pixel - glm::dvec2(pictureOffset(), 0);
}

int ViewApp::pictureOffset() const {
    if (!state_.showPanel) return 0;
    // Right of the panel (or its strip), with a margin: the picture clear of it.
    const float s = ui_->scale(), margin = 10 * s;
    const glm::dvec2 perUnit = 1.0 / toWindowUnits();  // framebuffer pixels per window unit
    const float strip = state_.panelStrip ? 3.5f * 13 * s + 2 * margin : 0;
    const PanelRect panel = panelRect(float(fbWidth_ / perUnit.x), float(fbHeight_ / perUnit.y), s);
    const float panelRight = state_.panelStrip ? strip : panel.x + panel.width + margin;
    return std::clamp(int(std::lround(panelRight * perUnit.x)), 0, std::max(0, fbWidth_ - 2));
}

int ViewApp::bounceViewLimit() const { return std::max(scene_.scene().render.maxBounces, 0) + 1; }

int ViewApp::currentPreset() const {
    if (scene_.path().empty()) return -1;
    std::error_code ec;
    for (std::size_t i = 0; i < presets_.size(); ++i)
        if (fs::equivalent(presets_[i], scene_.path(), ec)) return int(i);
    return -1;
}

std::vector<std::string> ViewApp::errors() const {
    std::vector<std::string> out;
    for (const Side& side : sides_)
        if (!side.program->error().empty())
            out.push_back((sides_.size() > 1 ? side.program->label() + ": " : "") + side.program->error());
    if (!scene_.error().empty()) out.push_back(scene_.error());
    if (!runtimeError_.empty()) out.push_back(runtimeError_);
    return out;
}

void ViewApp::toast(const std::string& message) {
    toast_ = message;
    toastUntil_ = Clock::now() + kToastTime;
}

void ViewApp::printStats() const {
    if (stats_.frames() == 0) return;
    const double ms = stats_.allWallMs();
    std::printf("raylab view: %zu frames at %dx%d (%s%s%s): median %.1f ms per frame (%.1f fps)", stats_.frames(),
                fbWidth_, fbHeight_, sides_[0].program->label().c_str(), sides_.size() > 1 ? " | " : "",
                sides_.size() > 1 ? sides_[1].program->label().c_str() : "", ms, ms > 0 ? 1000.0 / ms : 0.0);
    if (stats_.gpuFrames() > 0) std::printf(", %s %.1f ms", softwareRenderer_ ? "render" : "GPU", stats_.allGpuMs());
    std::printf("\n");
    if (!movingFrameMs_.empty()) {
        // The drag's own frame timer: every frame rendered while moving, from
        // the start of the frame to the swap.
        const double moving = FrameStats::median(movingFrameMs_);
        std::printf("raylab view: moving: %zu frames, median %.1f ms per frame (%.1f fps), render scale down to %.3f "
                    "(%dx%d), overhead %.1f ms\n",
                    movingFrameMs_.size(), moving, moving > 0 ? 1000.0 / moving : 0.0, lowestScale_,
                    std::max(1, int(std::lround(fbWidth_ * lowestScale_))),
                    std::max(1, int(std::lround(fbHeight_ * lowestScale_))), adaptive_.overheadMs());
        if (!fullRenderMs_.empty())
            std::printf("raylab view: still: %zu renders at full resolution, median %.1f ms\n", fullRenderMs_.size(),
                        FrameStats::median(fullRenderMs_));
    }
    if (!stillBackMs_.empty())
        std::printf("raylab view: still: the full picture back %.0f ms after the hand stopped (median of %zu, the "
                    "longest %.0f ms)\n",
                    FrameStats::median(stillBackMs_), stillBackMs_.size(),
                    *std::max_element(stillBackMs_.begin(), stillBackMs_.end()));
    if (refineBands_ > 0)
        std::printf("raylab view: still: still frames refined in %d band%s of about %.0f ms\n", refineBands_, refineBands_ == 1 ? "" : "s", kRefineBandMs);
    if (options_.stats && parts_.movingFrames() > 0) {
        const double interval = parts_.movingIntervalMs();
        std::printf("raylab view: moving: %.1f ms from swap to swap (%.1f fps)\n", interval,
                    interval > 0 ? 1000.0 / interval : 0.0);
        std::printf("raylab view: parts: %s\n", parts_.summary().c_str());
    }
    std::fflush(stdout);
}

}  // namespace rl
