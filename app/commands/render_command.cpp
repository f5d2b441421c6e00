// raylab render [SCENE] -o out.png [--hdr out.pfm] [--size WxH] [--spp N]
//               [--backend auto|egl|osmesa|glfw] [--impl DIR] [--cpu [--samples N] [--seed S]] [--view NAME]
// raylab render [SCENE] --ask X,Y [--impl DIR] [--size WxH] [--spp N]: the pixel
//               debugger's table for pixel (X, Y) from the top left, no picture
//               written (-o, --hdr and a --view other than final are refused)
#include "commands/commands.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "checks/pixel_hint.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "reference/environment_reference.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "render/pixel_debugger.h"
#include "shader/shader_library.h"

#include <climits>
#include <cmath>
#include <cstdint>
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
    int samples = 0;         // --cpu: environment samples per strategy per hit (0: the reference's default)
    std::uint64_t seed = 0;  // --cpu: the environment integral's seed (0: the reference's default)
    bool generic = false;
    std::string ask;  // "X,Y": the pixel debugger instead of a picture
    bool pngGiven = false;  // -o on the command line (--ask refuses it)
};

// One coordinate of --ask, whole: optional minus, digits; a value beyond
// the range of long long reads as that bound (outside any picture either way).
long long askCoordinate(const std::string& text, bool& ok) {
    std::size_t k = text.size() > 1 && text[0] == '-' ? 1 : 0;
    ok = k < text.size();
    long long value = 0;
    for (; k < text.size() && ok; ++k) {
        if (text[k] < '0' || text[k] > '9') ok = false;
        else if (value < (LLONG_MAX - 9) / 10) value = value * 10 + (text[k] - '0');
        else value = LLONG_MAX;
    }
    return text[0] == '-' ? -value : value;
}

// --ask X,Y: the pixel debugger's table (render/pixel_debugger.h) for the
// implementation of --impl, with the checker's hint for the first exercise
// whose value differs from the CPU reference's. Exit 0 either way: the
// table is the answer (a test reads its verdict line).
void runAsk(const RenderOptions& o) {
    const std::size_t comma = o.ask.find(',');
    bool okX = false, okY = false;
    const long long x = comma == std::string::npos ? 0 : askCoordinate(o.ask.substr(0, comma), okX);
    const long long y = comma == std::string::npos ? 0 : askCoordinate(o.ask.substr(comma + 1), okY);
    if (!okX || !okY)
        throw Error("--ask: expected X,Y (a pixel from the top left, e.g. 120,80), got '" + o.ask + "'");
    // Options that make a picture have nothing to do with the table: refused, not dropped.
    if (!o.pfm.empty()) throw Error("--ask: the pixel debugger writes no picture; --hdr does not apply");
    if (o.pngGiven) throw Error("--ask: the pixel debugger writes no picture; -o does not apply");
    if (o.view != "final")
        throw Error("--ask: the pixel debugger asks the final picture's values; --view " + o.view + " does not apply");
    Scene scene = sceneForCommand(o.scene, o.size);
    if (o.spp != 0) scene.render.spp = o.spp;
    const int w = scene.render.width, h = scene.render.height;
    if (x < 0 || y < 0 || x >= w || y >= h)
        throw Error("--ask: pixel (" + o.ask.substr(0, comma) + ", " + o.ask.substr(comma + 1) + ") is outside the " +
                    std::to_string(w) + "x" + std::to_string(h) + " picture");
    Implementation impl{o.impl.empty() ? defaultImplementationDir() : std::filesystem::path(o.impl), {}};
    std::error_code ec;
    if (!std::filesystem::is_directory(impl.dir, ec)) throw Error("--impl: " + impl.dir.string() + " is not a directory");
    auto context = createHeadlessContext(parseBackend(o.backend));
    const ShaderProgram program = buildPixelDebugProgram(impl, scene);
    PixelDebug debug = debugPixel(program, scene, scene.camera, w, h, int(x), h - 1 - int(y), impl.dir.string());
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
    if (!o.cpu && (o.samples != 0 || o.seed != 0))
        throw Error(std::string(o.samples != 0 ? "--samples" : "--seed") +
                    ": the CPU reference's environment integral only; add --cpu");
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
        ref::EnvironmentOptions environment;  // independent of the pixel filter (--spp)
        if (o.samples != 0) environment.samples = o.samples;
        if (o.seed != 0) environment.seed = o.seed;
        result = ref::renderCpu(scene, 0, environment);
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
    CLI::Option* output = cmd->add_option("-o,--output", options->png, "PNG to write (8-bit, display-encoded)")
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
    cmd->add_option("--samples", options->samples,
                    "With --cpu: environment light directions per strategy per hit (default 256; the pixel filter "
                    "stays --spp's)")
        ->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--seed", options->seed, "With --cpu: the seed of the environment integral (default 1)")
        ->check(CLI::Range(std::uint64_t(1), std::uint64_t(~0ull)));
    cmd->add_option("--ask", options->ask,
                    "Pixel debugger: X,Y from the top left; prints the program's values beside the CPU reference's (no picture)")
        ->check(notEmpty());
    cmd->add_flag("--generic", options->generic, "Use the generic shader, not one specialised to the scene");
    cmd->callback([options, output] {
        options->pngGiven = output->count() > 0;
        runRender(*options);
    });
}

}  // namespace rl
