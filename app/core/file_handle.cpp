// Open files over POSIX descriptors (see file_handle.h for the contracts).
#include "core/file_handle.h"

#include <cerrno>
#include <chrono>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl {

namespace {

std::error_code lastError() { return std::error_code(errno, std::generic_category()); }

fs::file_type typeOf(mode_t mode) {
    if (S_ISREG(mode)) return fs::file_type::regular;
    if (S_ISDIR(mode)) return fs::file_type::directory;
    if (S_ISCHR(mode)) return fs::file_type::character;
    if (S_ISBLK(mode)) return fs::file_type::block;
    if (S_ISFIFO(mode)) return fs::file_type::fifo;
    if (S_ISSOCK(mode)) return fs::file_type::socket;
    if (S_ISLNK(mode)) return fs::file_type::symlink;
    return fs::file_type::unknown;
}

}  // namespace

InputFile::InputFile(const fs::path& path, Links links) {
    int flags = O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC;
    if (links == Links::Refuse) flags |= O_NOFOLLOW;
    fd_ = ::open(path.c_str(), flags);
    if (fd_ < 0) {
        error_ = lastError();
        return;
    }
    struct stat info {};
    if (::fstat(fd_, &info) != 0) {
        error_ = lastError();
        ::close(fd_);
        fd_ = -1;
        return;
    }
    type_ = typeOf(info.st_mode);
    size_ = info.st_size > 0 ? std::uintmax_t(info.st_size) : 0;
}

InputFile::~InputFile() {
    if (fd_ >= 0) ::close(fd_);
}

std::ptrdiff_t InputFile::read(char* buffer, std::size_t bytes) {
    if (fd_ < 0) return -1;
    for (;;) {
        ssize_t n = ::read(fd_, buffer, bytes);
        // EAGAIN: opened without blocking; a regular file never says it, a FIFO might.
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n < 0) error_ = lastError();
        return std::ptrdiff_t(n);
    }
}

NewFile::NewFile(const fs::path& path) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ < 0) error_ = lastError();
}

NewFile::~NewFile() {
    if (fd_ >= 0) ::close(fd_);
}

bool NewFile::write(const char* data, std::size_t bytes) {
    if (fd_ < 0) return false;
    std::size_t written = 0;
    while (written < bytes) {
        ssize_t n = ::write(fd_, data + written, bytes - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_ = n < 0 ? lastError() : std::make_error_code(std::errc::io_error);
            return false;
        }
        written += std::size_t(n);
    }
    return true;
}

FileLock::FileLock(const fs::path& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) {
        error_ = lastError();
        return;
    }
    held_ = ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
}

bool FileLock::waitFor(double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (fd_ >= 0 && !held_ && std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        held_ = ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
    }
    return held_;
}

FileLock::~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
}

// POSIX stat(): std::filesystem has no inode, and its last_write_time clock
// cannot be compared across library versions anyway.
FileStamp fileStamp(const fs::path& file) {
    struct stat info {};
    FileStamp s;
    if (::stat(file.c_str(), &info) != 0) return s;
    s.exists = true;
#ifdef __APPLE__
    s.mtimeNs = (long long)info.st_mtimespec.tv_sec * 1000000000LL + info.st_mtimespec.tv_nsec;
#else
    s.mtimeNs = (long long)info.st_mtim.tv_sec * 1000000000LL + info.st_mtim.tv_nsec;
#endif
    s.size = (long long)info.st_size;
    s.inode = (unsigned long long)info.st_ino;
    return s;
}

}  // namespace rl
