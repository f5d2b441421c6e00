// raylab: a teaching framework for a GLSL fragment-shader ray tracer.
// This file only wires the subcommands (app/commands/) together and turns
// every error into one line on stderr and a non-zero exit status:
// 1 for a bad input or a failed run, 2 for a usage error, 3 for a bug.
#include "commands/commands.h"
#include "core/error.h"
#include "core/message.h"
#include "shader/program.h"

#include <algorithm>
#include <functional>
#include <filesystem>
#include <iostream>

namespace {

constexpr int kUsageError = 2;  // as getopt-based tools and CLI11's own "--help" conventions

// The registered commands, as "render, check, grade, bench, view or record".
std::string commandList(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"raylab: a GLSL ray tracer for teaching physically based rendering"};
    app.require_subcommand(1);
    rl::addRenderCommand(app);
    rl::addCheckCommand(app);
    rl::addGradeCommand(app);
    rl::addBenchCommand(app);
    rl::addCourseCommand(app);
#ifdef RAYLAB_WITH_GLFW
    rl::addViewCommand(app);
    rl::addRecordCommand(app);
#else
    app.add_subcommand("view", "The live window (not in this build)")->allow_extras()->callback([] {
        throw rl::Error("view: this build has no window support (RAYLAB_WITH_VIEW=OFF); use `raylab render`");
    });
#endif
    std::vector<std::string> names;  // what was registered above: one list, never out of date
    for (const CLI::App* command : app.get_subcommands(std::function<bool(CLI::App*)>{})) names.push_back(command->get_name());
    const std::string commands = commandList(names);
    auto isCommand = [&](const char* arg) { return std::find(names.begin(), names.end(), arg) != names.end(); };
    if (argc < 2) {
        std::cerr << "raylab: error: name a command: " << commands << " (raylab --help explains them)\n";
        return kUsageError;
    }
    const std::string first = argv[1];
    if (first[0] == '-' && first != "-h" && first != "--help") {
        std::cerr << "raylab: error: " << rl::quotedValue(first) << " before a command; expected " << commands
                  << " first (raylab --help explains them)\n";
        return kUsageError;
    }
    if (first[0] != '-' && !isCommand(argv[1])) {
        std::cerr << "raylab: error: " << rl::quotedValue(argv[1]) << " is not a command; expected " << commands << "\n";
        return kUsageError;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a command's own verdict (check: 1 when an exercise fails)
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help
        // CLI11's message on one line; its own printer adds a second line and exits 104-114.
        std::cerr << "raylab: error: " << rl::oneLine(e.what()) << "\n";
        return kUsageError;
    } catch (const rl::ShaderError& e) {
        // A compiler's report: one "file:line: error: ..." line per error, each followed by its
        // indented source line (app/shader/program.cpp), control characters escaped.
        std::cerr << "raylab: error: " << rl::printableLines(e.what(), 20000) << "\n";
        return 1;
    } catch (const rl::Error& e) {
        std::cerr << "raylab: error: " << rl::oneLine(e.what()) << "\n";
        return 1;
    } catch (const std::filesystem::filesystem_error& e) {  // a path the OS refuses (too long, a loop of links)
        std::cerr << "raylab: error: " << rl::oneLine(e.path1().string()) << ": " << e.code().message() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr << "raylab: error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "raylab: internal error: " << rl::oneLine(e.what()) << "\n";
        return 3;
    }
    return 0;
}
