// raylab view [SCENE] [--impl DIR] [--compare DIR] [--compare-model blinn-phong|pbr]
//             [--size WxH] [--view NAME]
//             [--frames N [--screenshot out.png]] [--script FILE] [--stats]
//             [--fullscreen] [--no-panel] [--no-captions] [--ui-scale S] [--panel-strip] [--generic]
// The live window (app/view/view_app.h); compiled only with RAYLAB_WITH_GLFW
// (main.cpp says so otherwise). docs/lecture.md is the user's guide.
#include "commands/commands.h"

#include "checks/pixel_hint.h"

#include "view/view_app.h"
#include "view/view_options.h"

namespace rl {

void addViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewOptions>();
    auto size = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("view", "Open the live ray tracer in a window (trackball, hot reload, panel)");
    cmd->add_option("scene", options->scene, "Scene file (.json); the embedded default scene when omitted");
    cmd->add_option("--impl", options->impl,
                    "Exercise implementations: a folder, or one exercise file such as a mutant (default: solutions/; exercises/ where there is none)")
        ->check(notEmpty());
    cmd->add_option("--compare", options->compare,
                    "Second implementation (folder or file), shown right of a draggable divider (split-screen wipe)");
    cmd->add_option("--compare-model", options->compareModel,
                    "Right of the divider, the same scene with another model: blinn-phong or pbr")
        ->check(CLI::IsMember({"blinn-phong", "pbr"}));
    cmd->add_option("--size", *size, "Window size WIDTHxHEIGHT (default: the scene's size)")->check(sizeValue());
    cmd->add_option("--view", options->view,
                    "Teaching view at start: final, d, g, f, fnv, diffuse, specular, ndotl, shadow, normals, bounce0, bounce1, ...; "
                    "with an environment: irradiance, prefiltered, env-scale, env-bias")
        ->capture_default_str();
    CLI::Option* frames = cmd->add_option("--frames", options->frames,
                                          "Render N frames (after the --script, if any), print timings, exit")
                              ->check(wholeNumberIn(1, 1000000));
    cmd->add_option("--screenshot", options->screenshot, "With --frames: save the last frame's picture as PNG")
        ->needs(frames)
        ->check(notEmpty());
    cmd->add_option("--script", options->script, "Scripted input, one command a line (see docs/lecture.md)");
    cmd->add_flag("--stats", options->stats, "Print the median frame time at exit");
    cmd->add_flag("--fullscreen", options->fullscreen, "Start fullscreen");
    cmd->add_flag("--no-panel", options->hidePanel, "Start with the panel hidden (Tab shows it)");
    cmd->add_flag("--panel-strip", options->panelStrip,
                  "Start with the panel folded to a narrow strip of view buttons (presenter layout; >> unfolds)");
    cmd->add_flag("--side-by-side", options->sideBySide,
                  "With --compare or --compare-model: two full pictures side by side (X toggles)");
    cmd->add_flag("--no-captions", options->hideCaptions,
                  "Start without the caption and colour bar on the picture (K shows them)");
    cmd->add_flag("--generic", options->generic,
                  "Draw with the generic program, not one specialised to the scene's structure (for comparison)");
    cmd->add_option("--ui-scale", options->uiScale,
                    "Panel and text scale, e.g. 2 for a projector (default: the screen's)")
        ->check(numberIn(0.5, 4.0));
    cmd->callback([options, size] {
        if (!size->empty()) {
            Size s = parseSize(*size);
            options->width = s.width;
            options->height = s.height;
        }
        options->probeHint = addProbeHint;  // the checker's hint for an asked pixel (checks/pixel_hint.h)
        ViewApp viewer(*options);
        const int status = viewer.run();
        if (status != 0) throw CLI::RuntimeError(status);
    });
}

}  // namespace rl
