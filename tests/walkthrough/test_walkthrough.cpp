// The student path, walked as the documents describe it (issue 9): in a
// scratch copy of the repository, run the commands of docs/exercises/README.md
// and of every handout exactly as they are written there (read from the
// Markdown, never retyped here), edit exercises/NN-*.glsl in place with wrong
// versions (tests/mutants/) and then the right one (solutions/), and check
// the verdicts, the checker output the documents show, and the files they
// promise. The copy has no build: ./raylab runs this build's binary through
// RAYLAB_BIN.
#include "course/exercise_registry.h"
#include "core/image.h"
#include "core/paths.h"
#include "support/test_support.h"
#include "walkthrough/doc_commands.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <chrono>
#include <iostream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rl;
using walkthrough::DocCommand;

namespace {

using test::shellQuoted;

test::CommandResult shell(const std::string& command) { return test::runShell(command); }

// A copy of the repository as a student's clone has it: the files git tracks
// (and new ones it does not ignore), from the working tree; no build. A git
// repository of its own, so that `git status` shows what the commands leave.
fs::path scratchClone(const std::string& name) {
    fs::path copy = test::freshTempDir(name);
    test::copyRepositoryFiles(copy);
    // solutions/ is what the build writes from the units (cmake/course.cmake):
    // a built instructor's repository has it.
    std::error_code ec;
    if (fs::is_directory(solutionsDir(), ec))
        fs::copy(solutionsDir(), copy / "solutions", fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    test::CommandResult init = shell("cd " + shellQuoted(copy.string()) + " && git init -q && git add -A");
    if (init.status != 0) throw std::runtime_error("git init in the scratch copy: " + init.output);
    return copy;
}

std::string verdictOf(const std::string& output, const std::string& id) {
    std::regex line("(^|\\n)" + id + " +(PASS|FAIL|NOT STARTED|COMPILE ERROR|TIMEOUT|CRASH)( |\\n)");
    std::smatch m;
    return std::regex_search(output, m, line) ? m[2].str() : "(no verdict line for " + id + ")";
}

// The text of function `name` in GLSL `text`: from its '{' to the matching '}'.
std::pair<std::size_t, std::size_t> functionBody(const std::string& text, const std::string& name) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex("(^|\\n)[A-Za-z0-9_]+\\s+" + name + "\\s*\\(")))
        throw std::runtime_error("no function " + name);
    std::size_t open = text.find('{', std::size_t(m.position(0)));
    int depth = 0;
    for (std::size_t k = open; k < text.size(); ++k) {
        depth += text[k] == '{' ? 1 : text[k] == '}' ? -1 : 0;
        if (depth == 0) return {open, k + 1};
    }
    throw std::runtime_error("unbalanced braces in " + name);
}

struct Walk {
    fs::path root;
    std::string binary = RAYLAB_BINARY;
    std::vector<std::pair<std::string, std::string>> checkRuns;  // (what was in place, output)
    std::set<std::string> verdictsSeen;
    int imageTriples = 0;  // check-output/NN/SCENE-{expected,got,diff}.png seen on disk

    test::CommandResult run(const std::string& command) {
        return shell("cd " + shellQuoted(root.string()) + " && env -u RAYLAB_ROOT RAYLAB_BIN=" + shellQuoted(binary) +
                     " timeout 300 bash -c " + shellQuoted(command));
    }
};

std::string where(const fs::path& doc, int line) { return doc.filename().string() + ":" + std::to_string(line); }

// Runs one documented command in the state `state` and checks what the
// documents promise about it. Returns its output.
test::CommandResult runDocumented(Walk& walk, const fs::path& doc, const DocCommand& c, const std::string& state) {
    std::string at = where(doc, c.line) + ": `" + c.text + "` (" + state + ")";
    if (c.text.rfind("./raylab view", 0) == 0) return {0, "(skipped: the live window needs a display)"};
    if (c.text.rfind("./raylab ", 0) != 0) {
        // Build commands: not run here (this test runs against the build it is
        // part of), but each must name a script or a preset that exists.
        static const std::regex part("\\s*&&\\s*");
        nlohmann::json presets = nlohmann::json::parse(test::readText(walk.root / "CMakePresets.json"));
        for (std::sregex_token_iterator p(c.text.begin(), c.text.end(), part, -1), end; p != end; ++p) {
            std::string command = *p;
            if (command.rfind("scripts/", 0) == 0) {
                fs::path script = walk.root / command.substr(0, command.find(' '));
                EXPECT_TRUE(fs::is_regular_file(script) && access(script.c_str(), X_OK) == 0) << at << ": no such script";
            } else if (command.rfind("cmake ", 0) == 0) {
                std::string preset = walkthrough::optionValue(command, "--preset");
                const char* kind = command.find("--build") != std::string::npos ? "buildPresets" : "configurePresets";
                bool found = false;
                for (const auto& p : presets[kind]) found = found || p["name"] == preset;
                EXPECT_TRUE(found) << at << ": no " << kind << " entry '" << preset << "' in CMakePresets.json";
            } else {
                ADD_FAILURE() << at << ": a command this walkthrough does not know how to follow";
            }
        }
        return {0, ""};
    }
    test::CommandResult r = walk.run(c.text);
    bool check = c.text.rfind("./raylab check", 0) == 0;
    if (!check) {
        EXPECT_EQ(r.status, 0) << at << " failed:\n" << r.output;
        for (const char* option : {"-o", "--output", "--hdr"}) {
            std::string file = walkthrough::optionValue(c.text, option);
            if (file.empty()) continue;
            EXPECT_TRUE(fs::is_regular_file(walk.root / file)) << at << ": " << file << " was not written";
            if (file.size() > 4 && file.substr(file.size() - 4) == ".png" && fs::is_regular_file(walk.root / file))
                EXPECT_GT(readPng((walk.root / file).string()).width, 0) << at;
        }
        return r;
    }
    // The pictures the checker names must be there.
    static const std::regex picture("(\\S*check-output/([0-9][0-9]-[a-z0-9-]+)/(\\S+)-(expected|got|diff)\\.png)");
    std::map<std::string, int> parts;
    for (std::sregex_iterator m(r.output.begin(), r.output.end(), picture), end; m != end; ++m) {
        fs::path png = (*m)[1].str();
        if (png.is_relative()) png = walk.root / png;
        EXPECT_TRUE(fs::is_regular_file(png)) << at << ": the checker names " << png << ", which is not there";
        if (fs::is_regular_file(png)) ++parts[(*m)[2].str() + "/" + (*m)[3].str()];
    }
    for (const auto& [scene, n] : parts) walk.imageTriples += n >= 3;
    static const std::regex verdict("(^|\\n)[0-9][0-9]-[a-z0-9-]+ +(PASS|FAIL|NOT STARTED|COMPILE ERROR|TIMEOUT|CRASH) ");
    for (std::sregex_iterator m(r.output.begin(), r.output.end(), verdict), end; m != end; ++m)
        walk.verdictsSeen.insert((*m)[2].str());
    walk.checkRuns.emplace_back(state + ", " + at, r.output);
    return r;
}

std::vector<DocCommand> docCommands(const fs::path& doc, bool checks) {
    std::vector<DocCommand> out;
    for (const DocCommand& c : walkthrough::commands(test::readText(doc)))
        if ((c.text.rfind("./raylab check", 0) == 0) == checks) out.push_back(c);
    return out;
}

}  // namespace

// The wrapper: one path for the program whichever build the student made.
TEST(Wrapper, SaysHowToBuildWhenNothingIsBuilt) {
    fs::path copy = test::freshTempDir("wrapper_nobuild");
    fs::copy_file(sourceRoot() / "raylab", copy / "raylab");
    test::CommandResult r = shell("env -u RAYLAB_BIN " + shellQuoted((copy / "raylab").string()) + " check");
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("scripts/build.sh"), std::string::npos) << r.output;
}

TEST(Wrapper, RunsTheNewerOfTheTwoBuilds) {
    fs::path copy = test::freshTempDir("wrapper_newer");
    fs::copy_file(sourceRoot() / "raylab", copy / "raylab");
    for (const char* build : {"build", "build-headless"}) {
        fs::create_directories(copy / build / "bin");
        test::writeText(copy / build / "bin" / "raylab", std::string("#!/bin/sh\necho ") + build + " \"$@\" \"$RAYLAB_ROOT\"\n");
        fs::permissions(copy / build / "bin" / "raylab", fs::perms::owner_all);
    }
    auto touch = [&](const char* build, int secondsAgo) {
        fs::last_write_time(copy / build / "bin" / "raylab", fs::file_time_type::clock::now() - std::chrono::seconds(secondsAgo));
    };
    std::string wrapper = "env -u RAYLAB_BIN -u RAYLAB_ROOT " + shellQuoted((copy / "raylab").string());
    touch("build", 100), touch("build-headless", 10);
    EXPECT_EQ(shell(wrapper + " check -e 1").output, "build-headless check -e 1 " + copy.string() + "\n");
    touch("build", 5);
    EXPECT_EQ(shell(wrapper + " check -e 1").output, "build check -e 1 " + copy.string() + "\n");
    fs::remove(copy / "build" / "bin" / "raylab");
    EXPECT_EQ(shell(wrapper + " render").output, "build-headless render " + copy.string() + "\n");
}

// The whole route, in the order a student takes it.
TEST(Walkthrough, EveryStudentDocumentAsWritten) {
    Walk walk;
    walk.root = scratchClone("walkthrough");
    const fs::path docs = walk.root / "docs" / "exercises";
    const fs::path readme = docs / "README.md";

    // 1. Your first ten minutes: build (checked, not run), render, check, all on the fresh stubs.
    ASSERT_FALSE(walkthrough::commands(test::readText(readme)).empty()) << "no commands found in " << readme;
    for (const DocCommand& c : walkthrough::commands(test::readText(readme))) {
        test::CommandResult r = runDocumented(walk, readme, c, "every exercise the shipped stub");
        if (c.text.rfind("./raylab check", 0) != 0) continue;
        EXPECT_NE(r.status, 0) << where(readme, c.line) << ": exit status 0 with nothing done";
        for (const ExerciseInfo& e : allExercises()) {
            bool selected = r.output.find(e.id) != std::string::npos;
            if (selected) EXPECT_EQ(verdictOf(r.output, e.id), "NOT STARTED") << where(readme, c.line) << "\n" << r.output;
        }
    }

    // 2. Every handout, in order, editing exercises/NN-*.glsl in place.
    std::map<std::string, std::vector<walkthrough::CodeBlock>> shownByExercise;
    std::vector<std::pair<fs::path, walkthrough::CodeBlock>> shown;
    for (const auto& entry : fs::directory_iterator(docs))
        if (entry.path().extension() == ".md")
            for (const auto& b : walkthrough::checkerOutputs(test::readText(entry.path()))) shown.emplace_back(entry.path(), b);

    for (const ExerciseInfo& e : allExercises()) {
        fs::path handout = walk.root / e.handout();
        fs::path file = walk.root / "exercises" / e.file();
        std::vector<DocCommand> checks = docCommands(handout, true), renders = docCommands(handout, false);
        ASSERT_FALSE(checks.empty()) << handout << " tells the student no way to check";
        auto checkAll = [&](const std::string& state, const std::vector<std::string>& allowed) {
            for (const DocCommand& c : checks) {
                test::CommandResult r = runDocumented(walk, handout, c, state);
                std::string v = verdictOf(r.output, e.id);
                EXPECT_TRUE(std::find(allowed.begin(), allowed.end(), v) != allowed.end())
                    << where(handout, c.line) << " with " << state << ": " << v << "\n" << r.output;
                EXPECT_EQ(r.status == 0, v == "PASS") << where(handout, c.line) << ": exit status " << r.status;
            }
        };
        // The fresh stub.
        checkAll("the shipped stub", {"NOT STARTED"});
        // Wrong versions: every mutant of this exercise.
        std::vector<fs::path> mutants;
        for (const auto& m : fs::directory_iterator(walk.root / "course" / e.id / "mutants"))
            mutants.push_back(m.path());
        std::sort(mutants.begin(), mutants.end());
        EXPECT_FALSE(mutants.empty()) << "no mutant of " << e.id;
        for (const fs::path& m : mutants) {
            fs::copy_file(m, file, fs::copy_options::overwrite_existing);
            checkAll("mutant " + m.filename().string(), {"FAIL", "COMPILE ERROR"});
        }
        // Half done: the solution with one function still the stub, where a document shows that.
        std::string stub = *shippedStub(e.file()), solution = test::readText(walk.root / "solutions" / e.file());
        static const std::regex notStarted("(\\w+) is not started");
        for (const auto& [doc, block] : shown) {
            std::smatch m;
            if (block.lines.front().rfind(e.id + " ", 0) != 0 || !std::regex_search(block.lines.front(), m, notStarted))
                continue;
            auto [s0, s1] = functionBody(stub, m[1].str());
            auto [t0, t1] = functionBody(solution, m[1].str());
            test::writeText(file, solution.substr(0, t0) + stub.substr(s0, s1 - s0) + solution.substr(t1));
            checkAll(m[1].str() + " still the stub", {"FAIL"});
        }
        // The right one, and the pictures the handout renders.
        fs::copy_file(walk.root / "solutions" / e.file(), file, fs::copy_options::overwrite_existing);
        checkAll("the solution", {"PASS"});
        for (const DocCommand& c : renders) runDocumented(walk, handout, c, "exercises 01-" + e.id + " done");
    }

    // 3. All ten done: the README's checks again, now every exercise passes.
    for (const DocCommand& c : docCommands(readme, true)) {
        test::CommandResult r = runDocumented(walk, readme, c, "every exercise the solution");
        EXPECT_EQ(r.status, 0) << where(readme, c.line) << "\n" << r.output;
        for (const ExerciseInfo& e : allExercises())
            if (r.output.find(e.id) != std::string::npos)
                EXPECT_EQ(verdictOf(r.output, e.id), "PASS") << where(readme, c.line) << "\n" << r.output;
    }

    // 4. The checker output the documents show is what the checker prints.
    for (const auto& [doc, block] : shown) {
        bool found = false;
        for (const auto& [state, output] : walk.checkRuns) found = found || walkthrough::showsOutput(block.lines, output);
        std::string text;
        for (const std::string& l : block.lines) text += "    " + l + "\n";
        EXPECT_TRUE(found) << where(doc, block.line) << " shows checker output that no documented command printed "
                           << "(on the stub, the mutants or the solution):\n" << text;
    }
    EXPECT_GT(shown.size(), 0u) << "no checker output found in the student documents";
    // Every verdict printed is one the README's table explains.
    std::string readmeText = test::readText(readme);
    for (const std::string& v : walk.verdictsSeen)
        EXPECT_NE(readmeText.find("| **" + v + "** |"), std::string::npos) << "verdict " << v << " is not in the README's table";
    EXPECT_TRUE(walk.verdictsSeen.count("PASS") && walk.verdictsSeen.count("FAIL") && walk.verdictsSeen.count("NOT STARTED"));
    // "the lines below the hint name three pictures in check-output/NN-name/"
    EXPECT_GT(walk.imageTriples, 0) << "no failing check left SCENE-expected/got/diff.png in check-output/";

    // 5. Nothing the documents made a student write shows up in `git status`.
    test::CommandResult status = shell("cd " + shellQuoted(walk.root.string()) + " && git status --porcelain --untracked-files=all");
    std::string untracked;
    std::istringstream lines(status.output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("??", 0) == 0) untracked += line + "\n";
    EXPECT_EQ(untracked, "") << "files the documents' commands wrote that git does not ignore";

    std::cout << walk.checkRuns.size() << " documented check runs, " << shown.size()
              << " blocks of checker output from the documents matched, " << walk.imageTriples
              << " check-output picture triples\n";
    if (!HasFailure()) fs::remove_all(walk.root);
    else std::cerr << "the scratch copy is kept for a look: " << walk.root << "\n";
}
