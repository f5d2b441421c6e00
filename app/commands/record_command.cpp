// raylab record [SCENE] -o DIR [--size WxH] [--frames N] [--orbit DEGREES]
//               [--sweep exposure|roughness|metallic:FROM:TO] [--view NAME] [--impl DIR]
//               [--no-captions] [--ui-scale S]
// Renders a scripted turntable orbit or a slider sweep offline, headless, at
// full resolution, into DIR/frame-0000.png ...; where ffmpeg is installed,
// also DIR/record.mp4 and DIR/record.gif. A slow laptop still gives a smooth
// clip for the lecture. Each frame carries the live view's caption and colour
// bar (view/caption_layer.h), drawn into the picture before it is read back;
// --no-captions leaves them out. docs/lecture.md, "Recording".
// Built with the window library (it shares the view's caption layer), so it
// exists where `raylab view` does.
#include "commands/commands.h"

#include "camera/trackball.h"
#include "core/error.h"
#include "core/image.h"
#include "core/isolated.h"
#include "core/message.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "shader/shader_library.h"
#include "view/caption_layer.h"
#include "view/view_caption.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>


namespace fs = std::filesystem;

namespace rl {
namespace {

struct RecordOptions {
    std::string scene;
    std::string out = "record";
    std::string size;
    int frames = 60;
    double orbit = 0;   // degrees about the scene's up over the whole clip
    std::string sweep;  // "exposure:0.25:4", "roughness:0:1", "metallic:0:1"
    std::string view = "final";
    std::string impl;
    int fps = 30;
    bool noCaptions = false;  // leave the caption and colour bar out
    float uiScale = 0;        // caption size; 0 = the frame height / 720 (at least 1), as a projector at 1080p gets 1.5
};

// Runs argv; true on exit status 0. Output goes to this process's stderr.
bool run(const std::vector<std::string>& args) { return runProgram(args); }

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        std::error_code ec;
        if (end > start && fs::exists(fs::path(dirs.substr(start, end - start)) / program, ec)) return true;
        start = end + 1;
    }
    return false;
}

void runRecord(const RecordOptions& o) {
    Scene scene = sceneForCommand(o.scene, o.size);
    std::string sweepName;
    double from = 0, to = 0;
    if (!o.sweep.empty()) {
        char name[32] = {};
        if (std::sscanf(o.sweep.c_str(), "%31[a-z]:%lf:%lf", name, &from, &to) != 3)
            throw Error("--sweep: expected NAME:FROM:TO, e.g. roughness:0:1, not '" + o.sweep + "'");
        sweepName = name;
        if (sweepName != "exposure" && sweepName != "roughness" && sweepName != "metallic")
            throw Error("--sweep: unknown value '" + sweepName + "' (expected exposure, roughness or metallic)");
        // inf or nan parse as numbers and made black frames with exit 0. 2^20 stops either way
        // is far past any picture (a display value of 1 at exposure 1 is 2^20 times too bright there).
        if (!std::isfinite(from) || !std::isfinite(to))
            throw Error("--sweep: FROM and TO must be finite numbers, not " + quotedValue(o.sweep));
        if (sweepName == "exposure" && !(from >= 0x1p-20 && to >= 0x1p-20 && from <= 0x1p20 && to <= 0x1p20))
            throw Error("--sweep: exposure must be between 2^-20 and 2^20 (about 1e-6 and 1e6), not " + quotedValue(o.sweep));
        if (sweepName != "exposure" && !(from >= 0 && from <= 1 && to >= 0 && to <= 1))
            throw Error("--sweep: " + sweepName + " must be in [0, 1]");
    }
    int bounce = 0;
    const View view = parseView(o.view, bounce);
    Implementation impl{o.impl.empty() ? defaultImplementationDir() : fs::path(o.impl), {}};
    if (!fs::is_directory(impl.dir)) throw Error("--impl: " + impl.dir.string() + " is not a directory");
    fs::create_directories(o.out);

    auto context = createHeadlessContext(Backend::Auto);
    // The generic program: a sweep changes values that specialisation compiles in.
    ShaderProgram program = buildRayTracer(impl, definesFor(scene, ImplementationFacts{}, Purpose::Generic));
    // The orbit is the live view's turntable (no roll): a drag of
    // height * degrees / 180 pixels turns by `degrees`.
    const Camera start = scene.camera;
    GlRenderer renderer;
    std::unique_ptr<CaptionLayer> captions;
    if (!o.noCaptions) captions = std::make_unique<CaptionLayer>();
    const float uiScale = o.uiScale > 0 ? o.uiScale : std::max(1.0f, float(scene.render.height) / 720.0f);
    for (int k = 0; k < o.frames; ++k) {
        const double t = o.frames > 1 ? double(k) / (o.frames - 1) : 0.0;
        Scene frameScene = scene;
        if (o.orbit != 0) {
            Trackball turntable(start, scene.render.width, scene.render.height);
            const glm::dvec2 centre(scene.render.width / 2.0, scene.render.height / 2.0);
            turntable.beginDrag(centre, Trackball::Mode::Turntable);
            turntable.drag(centre + glm::dvec2(scene.render.height * (o.orbit * t) / 180.0, 0.0));
            frameScene.camera = turntable.camera();
        }
        if (sweepName == "exposure") frameScene.render.exposure = from * std::pow(to / from, t);  // even in stops
        for (Sphere& s : frameScene.spheres) {
            if (sweepName == "roughness") s.material.roughness = from + (to - from) * t;
            if (sweepName == "metallic") s.material.metallic = from + (to - from) * t;
        }
        FrameSettings frame = frameFromScene(frameScene);
        frame.view = view;
        frame.viewBounce = bounce;
        renderer.setScene(frameScene);
        renderer.draw(program, frame);
        if (captions) {
            // Over the display colour only (the radiance target is not written
            // out), then both targets again for the next draw.
            gl::BindFramebuffer(GL_FRAMEBUFFER, renderer.framebuffer());
            const GLenum display = GL_COLOR_ATTACHMENT0, both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
            gl::DrawBuffers(1, &display);
            gl::Viewport(0, 0, frame.width, frame.height);
            captions->draw(viewCaption(view, bounce, frameScene, frameScene.model), true, {}, {}, frame.width,
                           frame.height, uiScale);
            gl::DrawBuffers(2, both);
        }
        const Rendering r = renderer.readBack();
        char name[32];
        std::snprintf(name, sizeof name, "frame-%04d.png", k);
        writePng((fs::path(o.out) / name).string(), r.display);
    }
    std::cout << fs::absolute(o.out).lexically_normal().string() << ": " << o.frames << " frames\n";
    if (!onPath("ffmpeg")) {
        std::cout << "raylab: ffmpeg not found: the image sequence only (apt-get install ffmpeg for a video)\n";
        return;
    }
    const std::string pattern = (fs::path(o.out) / "frame-%04d.png").string();
    const std::string fps = std::to_string(o.fps);
    const std::string mp4 = (fs::path(o.out) / "record.mp4").string(), gif = (fs::path(o.out) / "record.gif").string();
    // yuv420p and even sizes: every player plays it.
    if (run({"ffmpeg", "-loglevel", "error", "-y", "-framerate", fps, "-i", pattern, "-vf",
             "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", mp4}))
        std::cout << fs::absolute(mp4).lexically_normal().string() << "\n";
    else
        std::cerr << "raylab: warning: ffmpeg could not write " << mp4 << "\n";
    if (run({"ffmpeg", "-loglevel", "error", "-y", "-framerate", fps, "-i", pattern, gif}))
        std::cout << fs::absolute(gif).lexically_normal().string() << "\n";
}

}  // namespace

void addRecordCommand(CLI::App& app) {
    auto o = std::make_shared<RecordOptions>();
    CLI::App* cmd = app.add_subcommand(
        "record", "Render a turntable orbit or a slider sweep offline into an image sequence (and a video with ffmpeg)");
    cmd->add_option("scene", o->scene, "Scene file (.json); the embedded default scene when omitted");
    cmd->add_option("-o,--output", o->out, "Folder for frame-0000.png ... (and record.mp4, record.gif)")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Frame size WIDTHxHEIGHT (default: the scene's)");
    cmd->add_option("--frames", o->frames, "Number of frames")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--orbit", o->orbit, "Turntable orbit about the scene's up, degrees over the clip (e.g. 360)");
    cmd->add_option("--sweep", o->sweep, "Slider sweep NAME:FROM:TO, NAME = exposure, roughness or metallic");
    cmd->add_option("--view", o->view, "Teaching view, as raylab render --view")->capture_default_str();
    cmd->add_option("--impl", o->impl, "Exercise implementations (default: solutions/; exercises/ where there is none)");
    cmd->add_option("--fps", o->fps, "Frame rate of the video")->check(CLI::Range(1, 120))->capture_default_str();
    cmd->add_flag("--no-captions", o->noCaptions, "Frames without the caption and colour bar of the view");
    cmd->add_option("--ui-scale", o->uiScale, "Caption size (default: frame height / 720, at least 1)")
        ->check(CLI::Range(0.5, 4.0));
    cmd->callback([o] { runRecord(*o); });
}

}  // namespace rl
