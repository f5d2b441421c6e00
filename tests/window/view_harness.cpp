#include "window/view_harness.h"

#include "core/error.h"
#include "core/paths.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

extern char** environ;

namespace fs = std::filesystem;
using rl::test::readText;

namespace rl::wintest {
namespace {

std::vector<char*> cStrings(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (auto& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

// Waits for `pid` up to `timeout`; kills it after. Returns the exit status, -1 if killed.
int waitFor(pid_t pid, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    int status = 0;
    while (true) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (done < 0) return -1;
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

}  // namespace

Xvfb::Xvfb(int width, int height) {
    int fds[2];
    if (pipe(fds) != 0) throw Error("pipe failed");
    // -displayfd: Xvfb picks a free display number and writes it to the fd
    // once it accepts connections, so parallel tests never collide.
    const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
    std::vector<std::string> args = {"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", screen,
                                     "-nolisten", "tcp"};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    auto argv = cStrings(args);
    int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (rc != 0) {
        close(fds[0]);
        throw Error("cannot start Xvfb (install it with scripts/setup.sh): " + std::string(std::strerror(rc)));
    }
    std::string number;
    char c = 0;
    while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (number.empty()) throw Error("Xvfb did not report a display number");
    display_ = ":" + number;
}

Xvfb::~Xvfb() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitFor(pid_, std::chrono::seconds(10));
}

Process::Process(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
                 const fs::path& workDir) {
    static std::atomic<int> counter{0};
    const int n = counter++;
    outFile_ = workDir / ("process-" + std::to_string(n) + ".out");
    errFile_ = workDir / ("process-" + std::to_string(n) + ".err");
    std::map<std::string, std::string> merged;
    for (char** e = environ; *e; ++e) {
        std::string entry = *e;
        auto eq = entry.find('=');
        if (eq != std::string::npos) merged[entry.substr(0, eq)] = entry.substr(eq + 1);
    }
    for (const auto& [k, v] : env) {
        if (v.empty())
            merged.erase(k);
        else
            merged[k] = v;
    }
    std::vector<std::string> envStrings;
    for (const auto& [k, v] : merged) envStrings.push_back(k + "=" + v);
    std::vector<std::string> args = argv;
    auto cArgs = cStrings(args);
    auto cEnv = cStrings(envStrings);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, outFile_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, errFile_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    // The child starts in workDir: screenshots with relative names land there.
    const std::string shell = "cd \"$0\" && exec \"$@\"";
    std::vector<std::string> wrapped = {"/bin/sh", "-c", shell, workDir.string()};
    wrapped.insert(wrapped.end(), args.begin(), args.end());
    auto cWrapped = cStrings(wrapped);
    int rc = posix_spawn(&pid_, "/bin/sh", &actions, nullptr, cWrapped.data(), cEnv.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw Error("cannot start " + argv.front() + ": " + std::strerror(rc));
}

Process::~Process() {
    if (pid_ > 0) {
        kill(pid_, SIGKILL);
        waitFor(pid_, std::chrono::seconds(10));
    }
}

RunResult Process::wait(std::chrono::seconds timeout) {
    RunResult r;
    r.status = waitFor(pid_, timeout);
    pid_ = -1;
    r.out = readText(outFile_);
    r.err = readText(errFile_);
    return r;
}

std::map<std::string, std::string> windowEnv(const Xvfb& x) {
    return {{"DISPLAY", x.display()},
            {"LIBGL_ALWAYS_SOFTWARE", "1"},  // Mesa llvmpipe: the same renderer as the headless tests
            {"WAYLAND_DISPLAY", ""}};        // GLFW must use the X server above
}

RunResult runRaylab(const std::vector<std::string>& args, const std::map<std::string, std::string>& env,
                    const fs::path& workDir, std::chrono::seconds timeout) {
    std::vector<std::string> argv = {RAYLAB_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    Process p(argv, env, workDir);
    return p.wait(timeout);
}

bool waitForFile(const fs::path& file, std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!fs::exists(file)) {
        if (std::chrono::steady_clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

TempDir::TempDir() {
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("raylab-window-" + std::to_string(getpid()) + "-" + std::to_string(rd()));
    fs::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

void copySourceTree(const fs::path& root) {
    for (const char* dir : {"shaders", "solutions", "exercises", "scenes"})
        fs::copy(sourceRoot() / dir, root / dir, fs::copy_options::recursive);
}

PictureDiff comparePictures(const DisplayImage& a, const DisplayImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("pictures differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
    PictureDiff d;
    long off = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])));
            d.maxLsb = std::max(d.maxLsb, worst);
            if (worst > 2) ++off;
        }
    d.offFraction = double(off) / (double(a.width) * a.height);
    return d;
}

DisplayImage columns(const DisplayImage& image, int x0, int x1) {
    DisplayImage out{x1 - x0, image.height, std::vector<std::uint8_t>(std::size_t(x1 - x0) * image.height * 3)};
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) out.at(x - x0, y)[c] = image.at(x, y)[c];
    return out;
}

void maybeUpdateDocImage(const std::filesystem::path& shot, const std::string& name) {
    const char* update = std::getenv("RAYLAB_UPDATE_DOC_IMAGES");
    if (!update || std::string(update) != "1") return;
    const std::filesystem::path dir = sourceRoot() / "docs" / "images" / "lecture";
    std::filesystem::create_directories(dir);
    DisplayImage image = readPng(shot.string());
    while (image.width > 640) {
        DisplayImage half{image.width / 2, image.height / 2,
                          std::vector<std::uint8_t>(std::size_t(image.width / 2) * (image.height / 2) * 3)};
        for (int y = 0; y < half.height; ++y)
            for (int x = 0; x < half.width; ++x)
                for (int c = 0; c < 3; ++c)
                    half.at(x, y)[c] = std::uint8_t((image.at(2 * x, 2 * y)[c] + image.at(2 * x + 1, 2 * y)[c] +
                                                     image.at(2 * x, 2 * y + 1)[c] + image.at(2 * x + 1, 2 * y + 1)[c] + 2) /
                                                    4);
        image = half;
    }
    std::filesystem::create_directories((dir / name).parent_path());  // "every-view/..."
    writePng((dir / name).string(), image);
}

}  // namespace rl::wintest
