#include "view/file_watcher.h"

#include <algorithm>

namespace rl {

FileWatcher::FileWatcher(std::function<void()> onChange) : onChange_(std::move(onChange)) {
    thread_ = std::thread([this] { run(); });
}

FileWatcher::~FileWatcher() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void FileWatcher::watch(std::vector<std::filesystem::path> files) {
    std::vector<FileStamp> fresh;
    fresh.reserve(files.size());
    for (const auto& f : files) fresh.push_back(fileStamp(f));  // outside the lock: stat() can be slow
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<FileStamp> stamps;
    stamps.reserve(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        auto known = std::find(files_.begin(), files_.end(), files[i]);
        stamps.push_back(known != files_.end() ? stamps_[std::size_t(known - files_.begin())] : fresh[i]);
    }
    files_ = std::move(files);
    stamps_ = std::move(stamps);
}

void FileWatcher::run() {
    bool pending = false;  // a change seen at the last poll, reported once the files hold still
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, kPollPeriod, [this] { return stop_; });
        if (stop_) break;
        bool changedNow = false;
        for (std::size_t i = 0; i < files_.size(); ++i) {
            FileStamp now = fileStamp(files_[i]);
            if (now != stamps_[i]) {
                stamps_[i] = now;
                changedNow = true;
            }
        }
        // An editor's save can take several writes (truncate, write, rename);
        // waiting one quiet poll avoids compiling a half-written file.
        if (changedNow) {
            pending = true;
        } else if (pending) {
            pending = false;
            changed_ = true;
            if (onChange_) {
                lock.unlock();
                onChange_();
                lock.lock();
            }
        }
    }
}

}  // namespace rl
