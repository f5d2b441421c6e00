// raylab course [--markdown] [--from DIR]
// The course as the registry has it (course/manifest.txt and the units'
// unit.json): one line per exercise in the course's order, with its title,
// the functions its students write, its weight in the default rubric and its
// handout; then the units the manifest leaves out (framework code). With
// --markdown, the table the documents show (docs/exercises/README.md holds
// its output, and tests/docs/test_docs.cpp keeps the two equal), links
// relative to the folder DIR (default: the repository root).
#include "commands/commands.h"

#include "core/error.h"
#include "course/exercise_registry.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>

namespace rl {
namespace {

std::string functionList(const ExerciseInfo& e, bool markdown) {
    std::string out;
    for (const ExerciseFunction& f : e.functions)
        out += (out.empty() ? "" : ", ") + (markdown ? "`" + f.name + "`" : f.name);
    return out;
}

}  // namespace

std::string courseMarkdownTable(const std::string& from) {
    const std::filesystem::path base = from.empty() ? "." : from;
    std::string out = "| # | file | you write | handout |\n|---|---|---|---|\n";
    for (const ExerciseInfo& e : allExercises()) {
        const std::string link = std::filesystem::path(e.handout()).lexically_relative(base).generic_string();
        out += "| " + e.id.substr(0, 2) + " | `exercises/" + e.file() + "` | " + functionList(e, true) + " | [" + e.title +
               "](" + link + ")" + (e.optional ? " (optional)" : "") + " |\n";
    }
    return out;
}

void addCourseCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("course", "List the course's exercises (course/manifest.txt and its units)");
    auto markdown = std::make_shared<bool>(false);
    auto from = std::make_shared<std::string>();
    cmd->add_flag("--markdown", *markdown, "The table the documents show (docs/exercises/README.md)");
    cmd->add_option("--from", *from, "With --markdown: links relative to this folder of the repository")
        ->check(notEmpty());
    cmd->callback([markdown, from] {
        if (*markdown) {
            std::cout << courseMarkdownTable(*from);
            return;
        }
        std::size_t width = 0;
        for (const ExerciseInfo& e : allExercises()) width = std::max(width, e.id.size());
        for (const ExerciseInfo& e : allExercises())
            std::cout << std::left << std::setw(int(width) + 2) << e.id << e.title << " ("
                      << (e.optional ? "optional: a bonus, weight 0 in the default rubric" : std::to_string(e.weight) + " points")
                      << "): " << functionList(e, false) << "; handout " << e.handout() << "\n";
        for (const ExerciseInfo& e : frameworkUnits())
            std::cout << std::left << std::setw(int(width) + 2) << e.id << "not in the course: its solution is framework code ("
                      << functionList(e, false) << ")\n";
    });
}

}  // namespace rl
