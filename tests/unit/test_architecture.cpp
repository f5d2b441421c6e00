// Layers of app/: the operating system's process and file calls live in
// app/core only (core/isolated.h, core/process_pool.h, core/file_handle.h,
// core/file_io.h), so that a macOS or Windows port implements those files and
// nothing else (docs/decisions.md, "Child processes on macOS and Windows").
// Every file of app/ outside app/core/ is scanned for the POSIX headers and
// the process calls; comments and string literals do not count.
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// <sys/...> too, whatever follows the slash.
const std::set<std::string> kPosixHeaders = {"unistd.h", "spawn.h", "poll.h", "signal.h",
                                             "csignal",  "fcntl.h", "sys/*"};

// Process, signal, memory-sharing and lock calls. A member call (x.wait(),
// p->kill()) is not one of them.
const std::regex kPosixCall(
    R"((^|[^\w.>])(::)?(fork|vfork|waitpid|waitid|wait|wait3|wait4|kill|killpg|sigaction|signal|sigprocmask|)"
    R"(setrlimit|getrlimit|prlimit|pipe|pipe2|posix_spawn|posix_spawnp|execv|execve|execvp|execl|execlp|)"
    R"(setpgid|setsid|_exit|mmap|munmap|flock|fsync|popen)\s*\()");

// The text with comments and string and character literals blanked out
// (newlines kept, so line numbers stay).
std::string codeOnly(const std::string& text) {
    std::string out = text;
    enum { Code, Line, Block, String, Char } state = Code;
    for (std::size_t i = 0; i < out.size(); ++i) {
        char c = out[i], next = i + 1 < out.size() ? out[i + 1] : '\0';
        switch (state) {
            case Code:
                if (c == '/' && next == '/') state = Line;
                else if (c == '/' && next == '*') state = Block;
                else if (c == '"') state = String;
                else if (c == '\'') state = Char;
                else continue;
                if (state == Line || state == Block) out[i] = out[i + 1] = ' ', ++i;
                continue;
            case Line:
                if (c == '\n') state = Code;
                else out[i] = ' ';
                continue;
            case Block:
                if (c == '*' && next == '/') out[i] = out[i + 1] = ' ', ++i, state = Code;
                else if (c != '\n') out[i] = ' ';
                continue;
            case String:
            case Char:
                if (c == '\\') out[i] = ' ', out[i + 1] = out[i + 1] == '\n' ? '\n' : ' ', ++i;
                else if ((state == String && c == '"') || (state == Char && c == '\'')) state = Code;
                else if (c != '\n') out[i] = ' ';
                continue;
        }
    }
    return out;
}

bool forbiddenHeader(const std::string& header) {
    return kPosixHeaders.count(header) || header.rfind("sys/", 0) == 0;
}

// "file:line: #include <unistd.h>", "file:line: calls fork()" for each finding.
std::vector<std::string> findings(const std::string& shown, const std::string& text) {
    std::vector<std::string> out;
    static const std::regex include(R"(^\s*#\s*include\s*<([^>]+)>)"), directive(R"(^\s*#\s*include)");
    std::istringstream raw(text), code(codeOnly(text));
    std::string rawLine, codeLine;
    for (int n = 1; std::getline(raw, rawLine) && std::getline(code, codeLine); ++n) {
        std::smatch m;
        // The include from the raw line (a header name is no string literal),
        // only where the code line still has the directive (not commented out).
        if (codeLine.find('#') != std::string::npos && std::regex_search(codeLine, directive) &&
            std::regex_search(rawLine, m, include) &&
            forbiddenHeader(m[1].str()))
            out.push_back(shown + ":" + std::to_string(n) + ": #include <" + m[1].str() + ">");
        if (codeLine.find('(') == std::string::npos) continue;
        for (auto it = std::sregex_iterator(codeLine.begin(), codeLine.end(), kPosixCall); it != std::sregex_iterator();
             ++it)
            out.push_back(shown + ":" + std::to_string(n) + ": calls " + (*it)[3].str() + "()");
    }
    return out;
}

std::vector<fs::path> sourcesOutsideCore() {
    const fs::path app = rl::sourceRoot() / "app";
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(app)) {
        const fs::path rel = entry.path().lexically_relative(app);
        if (*rel.begin() == "core" || !entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext == ".cpp" || ext == ".h" || ext == ".hpp" || ext == ".cc" || ext == ".in") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST(Architecture, TheScannerSeesHeadersAndCallsButNotCommentsOrStrings) {
    EXPECT_EQ(findings("a.cpp", "#include <unistd.h>\n").size(), 1u);
    EXPECT_EQ(findings("a.cpp", "  #  include <sys/wait.h>\n").size(), 1u);
    EXPECT_EQ(findings("a.cpp", "#include <csignal>\n#include <cstdio>\n").size(), 1u);
    EXPECT_EQ(findings("a.cpp", "pid_t p = fork();\n"), std::vector<std::string>{"a.cpp:1: calls fork()"});
    EXPECT_EQ(findings("a.cpp", "int x;\n  ::kill (pid, 9);\n"), std::vector<std::string>{"a.cpp:2: calls kill()"});
    EXPECT_EQ(findings("a.cpp", "waitpid(-1, &s, WNOHANG); setrlimit(RLIMIT_CPU, &l);\n").size(), 2u);
    EXPECT_TRUE(findings("a.cpp", "// fork() and kill(pid) here\n/* #include <unistd.h>\n pipe(fds) */\n").empty());
    EXPECT_TRUE(findings("a.cpp", "auto s = \"kill(\"; char c = '(';\ncv.wait(lock); p->kill(); forked(1);\n").empty());
    EXPECT_TRUE(findings("a.cpp", "#include <string>\n#include \"core/isolated.h\"\n").empty());
}

TEST(Architecture, NoFileOutsideCoreIncludesPosixHeadersOrCallsProcessFunctions) {
    std::vector<fs::path> files = sourcesOutsideCore();
    ASSERT_GT(files.size(), 50u) << "app/ was not found under " << rl::sourceRoot();
    std::string report;
    for (const fs::path& file : files)
        for (const std::string& f : findings(fs::relative(file, rl::sourceRoot()).string(), rl::test::readText(file)))
            report += f + "\n";
    EXPECT_EQ(report, "") << "outside app/core/, a POSIX header or process call: move it behind core/isolated.h, "
                             "core/process_pool.h or core/file_handle.h";
}

// ---- Layers -------------------------------------------------------------------------------
//
// Each folder of app/ is one layer; a file may include its own folder and
// the folders of lower layers, never a higher one or another folder of its
// own rank (so no cycle can form). The same order is the link order of the
// per-layer libraries in CMakeLists.txt, so the linker holds it too.
namespace {

const std::map<std::string, int> kLayerRank = {
    {"core", 0},                                                  // scenes, files, images, processes
    {"course", 1}, {"gl", 1}, {"reference", 1}, {"camera", 1},    // the registry; GL; the CPU reference; the trackball
    {"shader", 2},                                                // GLSL assembly, readiness, programs
    {"render", 3},                                                // the renderer and its defines
    {"checks", 4}, {"bench", 4}, {"view", 4},                     // what uses the renderer
    {"grading", 5},                                               // over checks
    {"commands", 6},                                              // the command line over everything
};

// "file:line: includes X/..." for each include of `layer`'s file that runs
// upward or sideways; an unknown folder counts as upward.
std::vector<std::string> layerFindings(const std::string& shown, const std::string& layer, const std::string& text) {
    std::vector<std::string> out;
    static const std::regex include(R"(^\s*#\s*include\s*"([a-z_]+)/[^"]+")");
    const auto own = kLayerRank.find(layer);
    std::istringstream raw(text), code(codeOnly(text));
    std::string rawLine, codeLine;
    for (int n = 1; std::getline(raw, rawLine) && std::getline(code, codeLine); ++n) {
        std::smatch m;
        if (codeLine.find('#') == std::string::npos || !std::regex_search(rawLine, m, include)) continue;
        const std::string target = m[1].str();
        if (target == layer) continue;
        const auto other = kLayerRank.find(target);
        if (own == kLayerRank.end() || other == kLayerRank.end() || other->second >= own->second)
            out.push_back(shown + ":" + std::to_string(n) + ": " + layer + "/ includes " + target + "/");
    }
    return out;
}

}  // namespace

TEST(Architecture, TheLayerScannerSeesUpwardAndSidewaysIncludes) {
    EXPECT_TRUE(layerFindings("a.cpp", "render", "#include \"shader/program.h\"\n#include \"core/error.h\"\n").empty());
    EXPECT_EQ(layerFindings("a.cpp", "render", "#include \"checks/checker.h\"\n"),
              std::vector<std::string>{"a.cpp:1: render/ includes checks/"});
    EXPECT_EQ(layerFindings("a.cpp", "checks", "int x;\n#include \"view/panel.h\"\n").size(), 1u);  // sideways
    EXPECT_EQ(layerFindings("a.cpp", "core", "#include \"course/exercise_registry.h\"\n").size(), 1u);
    EXPECT_TRUE(layerFindings("a.cpp", "render", "// #include \"checks/checker.h\"\n").empty());
}

TEST(Architecture, EveryIncludeRunsDownTheLayers) {
    const fs::path app = rl::sourceRoot() / "app";
    std::string report;
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(app)) {
        const fs::path rel = entry.path().lexically_relative(app);
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h" && ext != ".in")) continue;
        if (std::distance(rel.begin(), rel.end()) < 2) continue;  // app/main.cpp: the top
        ++files;
        for (const std::string& f :
             layerFindings(fs::relative(entry.path(), rl::sourceRoot()).string(), rel.begin()->string(),
                           rl::test::readText(entry.path())))
            report += f + "\n";
    }
    EXPECT_GT(files, 100);
    // The units' C++ (course/NN-name/): probes.cpp is compiled into the checks
    // layer, reference.{h,cpp} into the reference layer (cmake/course.cmake).
    int units = 0;
    for (const auto& entry : fs::recursive_directory_iterator(rl::sourceRoot() / "course")) {
        const std::string name = entry.path().filename().string();
        const std::string layer = name == "probes.cpp" ? "checks" : name.rfind("reference.", 0) == 0 ? "reference" : "";
        if (!entry.is_regular_file() || layer.empty()) continue;
        ++units;
        for (const std::string& f : layerFindings(fs::relative(entry.path(), rl::sourceRoot()).string(), layer,
                                                  rl::test::readText(entry.path())))
            report += f + "\n";
    }
    EXPECT_GE(units, 10);
    EXPECT_EQ(report, "") << "an include against the layers (tests/unit/test_architecture.cpp, kLayerRank)";
}
