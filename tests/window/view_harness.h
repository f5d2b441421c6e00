// What the window tests share: a private X server (Xvfb, started per test
// process on a display number it picks itself, so tests run in parallel and
// never touch the developer's DISPLAY), running the real `raylab` binary with
// Mesa's software renderer, and comparing pictures.
#pragma once

#include "core/image.h"
#include "support/test_support.h"  // writeText, readText

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <sys/types.h>
#include <vector>

namespace rl::wintest {

// Xvfb on a free display (-displayfd), 1280x1024x24 unless told; stopped by the destructor.
class Xvfb {
public:
    explicit Xvfb(int width = 1280, int height = 1024);
    ~Xvfb();
    Xvfb(const Xvfb&) = delete;
    Xvfb& operator=(const Xvfb&) = delete;
    const std::string& display() const { return display_; }  // ":N"

private:
    pid_t pid_ = -1;
    std::string display_;
};

struct RunResult {
    int status = -1;       // exit status; -1 when killed by the time-out or a signal
    std::string out, err;  // stdout and stderr
};

// A child process with stdout/stderr going to files in `workDir`.
class Process {
public:
    // `env` entries replace (or, with an empty value, remove) variables of
    // this process's environment.
    Process(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
            const std::filesystem::path& workDir);
    ~Process();  // kills the child if it still runs
    Process(const Process&) = delete;
    Process& operator=(const Process&) = delete;

    // Waits for the exit; kills it after `timeout` (status -1).
    RunResult wait(std::chrono::seconds timeout);

private:
    pid_t pid_ = -1;
    std::filesystem::path outFile_, errFile_;
};

// The environment of a window test: this Xvfb, Mesa's llvmpipe.
std::map<std::string, std::string> windowEnv(const Xvfb& x);

// Runs `raylab ARGS...` to the end (at most `timeout`).
RunResult runRaylab(const std::vector<std::string>& args, const std::map<std::string, std::string>& env,
                    const std::filesystem::path& workDir, std::chrono::seconds timeout = std::chrono::seconds(180));

// Waits until `file` exists (or the time-out passes); true when it does.
bool waitForFile(const std::filesystem::path& file, std::chrono::seconds timeout);

// A fresh folder under the system temp directory, removed by the destructor.
class TempDir {
public:
    TempDir();
    ~TempDir();
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

// Copies shaders/, solutions/, exercises/ and scenes/ of the source tree to
// `root`, for tests that edit files (RAYLAB_ROOT=root).
void copySourceTree(const std::filesystem::path& root);

// Picture agreement, in 8-bit steps.
struct PictureDiff {
    int maxLsb = 0;          // largest channel difference
    double offFraction = 0;  // pixels off by more than 2 LSB in any channel
};
PictureDiff comparePictures(const DisplayImage& a, const DisplayImage& b);
// The columns [x0, x1) of `image`.
DisplayImage columns(const DisplayImage& image, int x0, int x1);

// With RAYLAB_UPDATE_DOC_IMAGES=1: copies the screenshot `shot` to
// docs/images/lecture/NAME, halved (2x2 box filter) until it is at most 640
// pixels wide, so the repository keeps them small. Otherwise nothing.
void maybeUpdateDocImage(const std::filesystem::path& shot, const std::string& name);

}  // namespace rl::wintest
