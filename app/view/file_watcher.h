// Live reload, the glslViewer way: a thread polls the files' modification
// time, size and inode (so editors that save by writing a new file and
// renaming it over the old one are seen too) and only raises a flag; the GL
// thread takes the flag and does the GL work. One watcher per group of files
// that is reloaded together (a shader's sources, a scene file).
#pragma once

#include "core/file_handle.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rl {

class FileWatcher {
public:
    // How often the files are polled. 50 ms: a change is reported within two
    // polls (one to see it, one to see it settled), well inside the half
    // second the live view promises, and ~30 stat() calls 20 times a second
    // cost nothing.
    static constexpr std::chrono::milliseconds kPollPeriod{50};

    // `onChange` (optional) runs on the watcher thread after the flag is
    // raised, e.g. glfwPostEmptyEvent() to wake an idle event loop.
    explicit FileWatcher(std::function<void()> onChange = {});
    ~FileWatcher();  // stops and joins the thread
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // Replaces the watched files. Files watched before keep the state last
    // seen (so an edit made while the caller was busy rebuilding is still
    // reported); new ones start from their current state.
    void watch(std::vector<std::filesystem::path> files);
    // True once after any watched file changed, appeared or disappeared.
    bool takeChange() { return changed_.exchange(false); }

private:
    void run();

    std::function<void()> onChange_;
    std::mutex mutex_;  // guards files_, stamps_, stop_
    std::condition_variable wake_;
    std::vector<std::filesystem::path> files_;
    std::vector<FileStamp> stamps_;
    bool stop_ = false;
    std::atomic<bool> changed_{false};
    std::thread thread_;
};

}  // namespace rl
