// raylab course [--markdown] [--from DIR] [--record DIR]
// The course as the registry has it (course/manifest.txt and the units'
// unit.json): one line per exercise in the course's order, with its title,
// the functions its students write, its weight in the default rubric and its
// handout; then the units the manifest leaves out (framework code). With
// --markdown, the table the documents show (docs/exercises/README.md holds
// its output, and tests/docs/test_docs.cpp keeps the two equal), links
// relative to the folder DIR (default: the repository root). With --record,
// what a student edition needs from the reference, written under DIR as the
// edition lays it out (scripts/student-edition.sh): course/NN-name/probes.json
// for each exercise (checks/probe_data.h), recorded/check-scenes/NAME.pfm and
// .png (the check scenes' reference pictures) and recorded/split-sum-32-32.json
// (the environment light's table at its default settings).
#include "commands/commands.h"

#include "checks/checker.h"
#include "checks/probe_data.h"
#include "core/error.h"
#include "core/file_io.h"
#include "course/exercise_registry.h"
#include "reference/cpu_reference.h"
#include "reference/split_sum.h"
#include "render/environment_resources.h"

#include <nlohmann/json.hpp>

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

// Everything --record writes; the folders are made as needed.
void recordForEdition(const std::filesystem::path& dir) {
    if (!ref::referenceInThisCopy())
        throw Error("--record: not in this copy: a student edition has no reference to record from");
    namespace fs = std::filesystem;
    for (const ExerciseInfo& e : allExercises()) {
        const fs::path file = dir / e.unitDir() / "probes.json";
        fs::create_directories(file.parent_path());
        writeFileAtomic(file, recordProbes(unitProbes(e.id)).dump() + "\n");
    }
    const fs::path scenes = dir / "recorded" / "check-scenes";
    fs::create_directories(scenes);
    for (const CheckScene& c : makeCheckScenes()) {
        writePfm((scenes / (c.name + ".pfm")).string(), c.reference.radiance);
        writePng((scenes / (c.name + ".png")).string(), c.reference.display);
    }
    const EnvironmentSettings defaults;
    nlohmann::json table = nlohmann::json::array();
    for (const glm::dvec2& v : ref::splitSumTable(defaults.tableSize, defaults.tableSamples)) {
        table.push_back(v.x);
        table.push_back(v.y);
    }
    writeFileAtomic(dir / "recorded" /
                        ("split-sum-" + std::to_string(defaults.tableSize) + "-" + std::to_string(defaults.tableSamples) +
                         ".json"),
                    table.dump() + "\n");
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
    auto record = std::make_shared<std::string>();
    cmd->add_option("--record", *record,
                    "Write what a student edition needs from the reference under DIR (scripts/student-edition.sh)")
        ->check(notEmpty());
    cmd->callback([markdown, from, record] {
        if (!record->empty()) {
            recordForEdition(*record);
            return;
        }
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
