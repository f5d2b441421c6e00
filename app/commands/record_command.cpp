// raylab record [SCENE] -o DIR [--size WxH] [--frames N] [--orbit DEGREES]
//               [--sweep exposure|roughness|metallic:FROM:TO] [--view NAME] [--impl DIR]
//               [--no-captions] [--ui-scale S]
// Renders a scripted turntable orbit or a slider sweep offline, headless, at
// full resolution, into DIR/frame-0000.png ..., then DIR/record.mp4 and a
// palette-optimised DIR/record.gif with ffmpeg (without ffmpeg: the frames,
// one line saying what to install, exit 1). A slow laptop still gives a
// smooth clip for the lecture. The GIF and PNG sizes are estimated before
// the first frame is rendered. Each frame carries the live view's caption and colour
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

#include <algorithm>
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
    int gifFps = 15;          // the GIF's frame rate (at most --fps): every other frame of a 30 fps clip
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

// Bytes per pixel of one frame, measured on the 120-frame 1280x720 orbit of
// the lecture scene (docs/lecture.md, "Recording"): the GIF 4,938,248 bytes
// for 60 frames (0.089), the PNG frames 21.9 MB for 120 (0.198). A sweep
// changes less of the picture than an orbit and gives smaller GIFs; the
// estimate is for the worst case the docs show.
constexpr double kGifBytesPerPixel = 0.09;
constexpr double kPngBytesPerPixel = 0.2;

int gifFrames(const RecordOptions& o) {
    if (o.gifFps >= o.fps) return o.frames;
    return std::max(1, int(std::lround(double(o.frames) * o.gifFps / o.fps)));
}

std::string megabytes(double bytes) {
    char text[32];
    if (bytes < 1e6)
        std::snprintf(text, sizeof text, "%.0f kB", std::max(1.0, bytes / 1e3));
    else
        std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
    return text;
}

// One line, before the first frame is rendered.
std::string sizeEstimate(const RecordOptions& o, int width, int height, bool haveFfmpeg) {
    const double pixels = double(width) * height;
    const std::string frames = "raylab: recording " + std::to_string(o.frames) + " frames of " + std::to_string(width) +
                               "x" + std::to_string(height) + ": about " +
                               megabytes(kPngBytesPerPixel * pixels * o.frames) + " of PNG frames";
    if (!haveFfmpeg) return frames + ", no video (ffmpeg is not installed)\n";
    return frames + " and a GIF of about " + megabytes(kGifBytesPerPixel * pixels * gifFrames(o)) + " (" +
           std::to_string(gifFrames(o)) + " frames at " + std::to_string(std::min(o.gifFps, o.fps)) + " fps)\n";
}

// ffmpeg ARGS into DIR/NAME, through DIR/NAME.part: an earlier file of that
// name stays until the new one is complete.
void encode(const std::string& dir, const std::string& name, const std::string& format, std::vector<std::string> args) {
    const fs::path file = fs::path(dir) / name, part = fs::path(dir) / (name + ".part");
    args.insert(args.begin(), {"ffmpeg", "-nostdin", "-loglevel", "error", "-y"});
    args.insert(args.end(), {"-f", format, part.string()});
    if (!run(args)) {
        std::error_code ec;
        fs::remove(part, ec);
        throw Error("ffmpeg could not write " + file.string() + " (its message is above)");
    }
    fs::rename(part, file);
    std::error_code ec;
    const auto bytes = fs::file_size(file, ec);
    std::cout << fs::absolute(file).lexically_normal().string() << " (" << megabytes(ec ? 0.0 : double(bytes))
              << ")\n";
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
    std::cout << sizeEstimate(o, scene.render.width, scene.render.height, onPath("ffmpeg")) << std::flush;

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
    // Frames past this clip's end, from a longer recording into the same
    // folder, would run on in the video (ffmpeg reads frame-%04d.png until a
    // number is missing): the folder's frames are this clip's.
    for (int k = o.frames;; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%04d.png", k);
        std::error_code ec;
        if (!fs::remove(fs::path(o.out) / name, ec)) break;
    }
    const std::string dir = fs::absolute(o.out).lexically_normal().string();
    std::cout << dir << ": " << o.frames << " frames\n";
    if (!onPath("ffmpeg"))
        throw Error("ffmpeg not found: " + dir + "/frame-*.png are written, record.mp4 and record.gif are not "
                    "(install ffmpeg: apt-get install ffmpeg, or scripts/setup.sh --window)");
    const std::string pattern = (fs::path(o.out) / "frame-%04d.png").string();
    const std::string fps = std::to_string(o.fps);
    // yuv420p and even sizes: every player plays it.
    encode(o.out, "record.mp4", "mp4",
           {"-framerate", fps, "-i", pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"});
    // One palette of 256 colours made from the whole clip (palettegen), the
    // frames mapped onto it with an ordered dither (paletteuse): ffmpeg's
    // default GIF uses a fixed palette with error diffusion, which both bands
    // and compresses badly (the 120-frame 720p orbit of docs/lecture.md: 39.7 MB
    // before, 4.9 MB now). Bayer scale 5 is the finest pattern and the
    // smallest file; sierra2_4a dithering gave 11.4 MB, no dither 6.2 MB with
    // visible bands on the spheres. Half the frame rate halves the size; the
    // MP4 keeps every frame.
    const std::string rate = o.gifFps < o.fps ? "fps=" + std::to_string(o.gifFps) + "," : "";
    encode(o.out, "record.gif", "gif",
           {"-framerate", fps, "-i", pattern, "-filter_complex",
            "[0:v]" + rate + "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=5"});
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
    cmd->add_option("--impl", o->impl, "Exercise implementations (default: solutions/; exercises/ where there is none)")
        ->check(notEmpty());
    cmd->add_option("--fps", o->fps, "Frame rate of the video")->check(CLI::Range(1, 120))->capture_default_str();
    cmd->add_option("--gif-fps", o->gifFps, "Frame rate of the GIF, at most --fps (fewer frames, a smaller file)")
        ->check(CLI::Range(1, 120))
        ->capture_default_str();
    cmd->add_flag("--no-captions", o->noCaptions, "Frames without the caption and colour bar of the view");
    cmd->add_option("--ui-scale", o->uiScale, "Caption size (default: frame height / 720, at least 1)")
        ->check(CLI::Range(0.5, 4.0));
    cmd->callback([o] { runRecord(*o); });
}

}  // namespace rl
