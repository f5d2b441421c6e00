// raylab: a teaching framework for a GLSL fragment-shader ray tracer.
// This file only wires the subcommands (app/commands/) together and turns
// every error into one line on stderr and a non-zero exit status.
#include "commands/commands.h"
#include "core/error.h"

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"raylab: a GLSL ray tracer for teaching physically based rendering"};
    app.require_subcommand(1);
    rl::addRenderCommand(app);
    rl::addCheckCommand(app);
    rl::addGradeCommand(app);
    rl::addBenchCommand(app);
#ifdef RAYLAB_WITH_GLFW
    rl::addViewCommand(app);
    rl::addRecordCommand(app);
#else
    app.add_subcommand("view", "The live window (not in this build)")->allow_extras()->callback([] {
        throw rl::Error("view: this build has no window support (RAYLAB_WITH_GLFW=OFF); use `raylab render`");
    });
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a command's own verdict (check: 1 when an exercise fails)
    } catch (const CLI::ParseError& e) {
        return app.exit(e);  // usage errors: CLI11's message and its non-zero exit status
    } catch (const rl::Error& e) {
        std::cerr << "raylab: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "raylab: internal error: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
