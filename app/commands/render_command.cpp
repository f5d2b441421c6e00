// raylab render [SCENE] -o out.png [--hdr out.pfm] [--size WxH] [--spp N]
//               [--backend auto|egl|osmesa|glfw] [--impl DIR] [--cpu] [--view NAME]
// raylab render [SCENE] --ask X,Y [--impl DIR] [--size WxH]: the pixel debugger's
//               table for pixel (X, Y) from the top left, no picture written
#include "commands/commands.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "checks/pixel_hint.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "render/pixel_debugger.h"
#include "shader/shader_library.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace rl {

namespace {

struct RenderOptions {
    std::string scene;
    std::string png = "render.png";
    std::string pfm;
    std::string size;
    int spp = 0;
    std::string backend = "auto";
    std::string impl;
    std::string view = "final";
    bool cpu = false;
    bool generic = false;
    std::string ask;  // "X,Y": the pixel debugger instead of a picture
};

// --ask X,Y: the pixel debugger's table (render/pixel_debugger.h) for the
// implementation of --impl, with the checker's hint for the first exercise
// whose value differs from the CPU reference's. Exit 0 either way: the
// table is the answer (a test reads its verdict line).
void runAsk(const RenderOptions& o) {
    int x = -1, y = -1;
    char rest = 0;
    if (std::sscanf(o.ask.c_str(), "%d,%d%c", &x, &y, &rest) != 2)
        throw Error("--ask: expected X,Y (a pixel from the top left, e.g. 120,80), got '" + o.ask + "'");
    Scene scene = sceneForCommand(o.scene, o.size);
    if (o.spp != 0) scene.render.spp = o.spp;
    const int w = scene.render.width, h = scene.render.height;
    if (x < 0 || y < 0 || x >= w || y >= h)
        throw Error("--ask: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                    std::to_string(w) + "x" + std::to_string(h) + " picture");
    Implementation impl{o.impl.empty() ? defaultImplementationDir() : std::filesystem::path(o.impl), {}};
    std::error_code ec;
    if (!std::filesystem::is_directory(impl.dir, ec)) throw Error("--impl: " + impl.dir.string() + " is not a directory");
    auto context = createHeadlessContext(parseBackend(o.backend));
    const ShaderProgram program = buildPixelDebugProgram(impl, scene);
    PixelDebug debug = debugPixel(program, scene, scene.camera, w, h, x, h - 1 - y, impl.dir.string());
    addProbeHint(debug, impl);
    std::cout << formatPixelDebug(debug) << std::flush;
}

// The PNG and the PFM of one render, both replaced or neither: each is
// written in full beside its destination first (a full disk fails there,
// leaving both old files as they were), then both are renamed into place.
void writeRenderOutputs(const std::string& png, const std::string& pfm, const Rendering& result) {
    namespace fs = std::filesystem;
    if (pfm.empty()) {
        writePng(png, result.display);
        return;
    }
    const std::string pngPart = png + ".raylab-part", pfmPart = pfm + ".raylab-part";
    std::error_code ec;
    try {
        writePng(pngPart, result.display);
        writePfm(pfmPart, result.radiance);
    } catch (...) {
        fs::remove(pngPart, ec);
        fs::remove(pfmPart, ec);
        throw;
    }
    fs::rename(pfmPart, pfm, ec);
    if (ec) {
        fs::remove(pngPart, ec);
        fs::remove(pfmPart, ec);
        throw Error(pfm + ": cannot be written (" + ec.message() + "); " + png + " was left as it was");
    }
    fs::rename(pngPart, png, ec);
    if (ec) {
        fs::remove(pngPart, ec);
        throw Error(png + ": cannot be written (" + ec.message() + ")");
    }
}

void runRender(const RenderOptions& o) {
    if (!o.ask.empty()) {
        if (o.cpu) throw Error("--ask: the pixel debugger asks the GL program; --cpu has no program to ask");
        return runAsk(o);
    }
    requireOutputPath(o.png, "PNG");
    if (!o.pfm.empty()) requireOutputPath(o.pfm, "PFM");
    if (!o.pfm.empty()) {
        std::error_code ec;
        const std::filesystem::path a = std::filesystem::weakly_canonical(o.png, ec),
                                    b = std::filesystem::weakly_canonical(o.pfm, ec);
        if (a == b) throw Error("--hdr: " + o.pfm + " is also the PNG of -o: give the PFM a file of its own");
    }
    Scene scene = sceneForCommand(o.scene, o.size);
    if (o.spp != 0) scene.render.spp = o.spp;  // a square from 1 to 1024 (the option's validator)
    int bounce = 0;
    View view = parseView(o.view, bounce);

    Rendering result;
    if (o.cpu) {
        if (view != View::Final) throw Error("--view: the CPU reference renders the final image only");
        result = ref::renderCpu(scene);
    } else {
        Backend backend = parseBackend(o.backend);
        Implementation impl{o.impl.empty() ? defaultImplementationDir() : std::filesystem::path(o.impl), {}};
        std::error_code ec;
        if (!std::filesystem::is_directory(impl.dir, ec))
            throw Error("--impl: " + impl.dir.string() + " is not a directory");
        auto context = createHeadlessContext(backend);
        // The picture (or a bounce view): the program for this picture, from
        // this camera; the term views need every view (render/define_table.h).
        const Purpose purpose = o.generic ? Purpose::Generic : isPictureView(view) ? Purpose::Picture : Purpose::EveryView;
        // Whatever the files: one program built from shaders/ and them,
        // specialised to this picture (render/define_table.h).
        PictureProgram picture = buildPictureProgram(impl, definesFor(scene, implementationFacts(impl), purpose));
        FrameSettings frame = frameFromScene(scene);
        frame.view = view;
        frame.viewBounce = bounce;
        result = renderOnce(picture, scene, frame);
    }
    // No NaN or Inf leaves the renderer (issue #23): a scene the shader cannot
    // carry is refused before rendering (core/float_range.h); a non-finite
    // value here is raylab's bug, reported as an internal error (exit 3, which
    // the fuzzer fails on) before any output is written.
    if (std::string problem = nonFiniteProblem(result.radiance); !problem.empty())
        throw std::logic_error(o.scene + ": " + problem + "; nothing was written (a bug in raylab: please report it with the scene)");
    writeRenderOutputs(o.png, o.pfm, result);
    std::cout << std::filesystem::absolute(o.png).lexically_normal().string() << "\n";
    if (!o.pfm.empty()) std::cout << std::filesystem::absolute(o.pfm).lexically_normal().string() << "\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene headless to PNG (and PFM)");
    cmd->add_option("scene", options->scene, "Scene file (.json); the embedded default scene when omitted")
        ->check(notEmpty());
    cmd->add_option("-o,--output", options->png, "PNG to write (8-bit, display-encoded)")
        ->capture_default_str()
        ->check(notEmpty());
    cmd->add_option("--hdr", options->pfm, "Also write linear radiance as PFM")->check(notEmpty());
    cmd->add_option("--size", options->size, "Override the scene's size, WIDTHxHEIGHT")->check(sizeValue());
    cmd->add_option("--spp", options->spp, "Override samples per pixel (a square number)")
        ->check(squareNumberIn(1, 1024));
    cmd->add_option("--backend", options->backend, "OpenGL backend: auto, egl, osmesa or glfw (a hidden window)")->capture_default_str();
    cmd->add_option("--impl", options->impl, "Folder of exercise implementations (default: solutions/; exercises/ where there is none)")
        ->check(notEmpty());
    cmd->add_option("--view", options->view, "Teaching view: final, d, g, f, fnv, diffuse, specular, ndotl, shadow, normals, bounce0, bounce1, ...; "
                    "with an environment: irradiance, prefiltered, env-scale, env-bias")
        ->capture_default_str();
    cmd->add_flag("--cpu", options->cpu, "Render with the double-precision CPU reference instead of OpenGL");
    cmd->add_option("--ask", options->ask,
                    "Pixel debugger: X,Y from the top left; prints the program's values beside the CPU reference's (no picture)")
        ->check(notEmpty());
    cmd->add_flag("--generic", options->generic, "Use the generic shader, not one specialised to the scene");
    cmd->callback([options] { runRender(*options); });
}

}  // namespace rl
