// Open files, for what std::filesystem cannot do safely: reading a path
// without blocking on a FIFO and without following a link, creating a file
// that must not exist yet (never through a link), an exclusive lock that goes
// with the process, and a file's change stamp. With file_io.h, the only
// place where raylab calls the operating system's file functions (open,
// fstat, flock, stat); tests/unit/test_architecture.cpp keeps it so.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>

namespace rl {

// A file opened for reading without blocking (a FIFO does not wait for a
// writer) and never becoming the controlling terminal. Check ok() first;
// type() says what was opened, for refusing anything but a regular file.
class InputFile {
public:
    enum class Links { Follow, Refuse };  // Refuse: a link as the last component fails to open (ELOOP)
    explicit InputFile(const std::filesystem::path& path, Links links = Links::Follow);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    bool ok() const { return fd_ >= 0; }
    // Why it did not open, or why the last read failed: "No such file or
    // directory" (std::errc::no_such_file_or_directory), ...
    const std::error_code& error() const { return error_; }
    std::filesystem::file_type type() const { return type_; }  // of the open file
    std::uintmax_t size() const { return size_; }               // when it was opened

    // Up to `bytes` bytes into `buffer`: the count read, 0 at the end, -1 on
    // an error (error() says which). Interrupted reads are retried.
    std::ptrdiff_t read(char* buffer, std::size_t bytes);

private:
    int fd_ = -1;
    std::error_code error_;
    std::filesystem::file_type type_ = std::filesystem::file_type::none;
    std::uintmax_t size_ = 0;
};

// A file created by this object, that did not exist before (O_EXCL: a second
// writer of the same name fails with exists()) and is never created through a
// link (a link in its place fails too), mode 0644 before the umask.
class NewFile {
public:
    explicit NewFile(const std::filesystem::path& path);
    ~NewFile();
    NewFile(const NewFile&) = delete;
    NewFile& operator=(const NewFile&) = delete;

    bool ok() const { return fd_ >= 0; }
    bool exists() const { return error_ == std::errc::file_exists; }  // the name was taken
    const std::error_code& error() const { return error_; }
    // Writes all of it; false on an error (error() says which).
    bool write(const char* data, std::size_t bytes);

private:
    int fd_ = -1;
    std::error_code error_;
};

// An exclusive lock on a lock file (created if missing) while the object
// lives; never waits. The lock goes with the process however that ends, and
// child processes forked while it is held share it.
class FileLock {
public:
    explicit FileLock(const std::filesystem::path& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    bool held() const { return held_; }
    // Tries again every 50 ms for at most `seconds` while another holder has
    // it; returns held().
    bool waitFor(double seconds);
    // Set when the lock file cannot be opened or created; clear (and held()
    // false) when another holder has the lock.
    const std::error_code& error() const { return error_; }

private:
    int fd_ = -1;
    bool held_ = false;
    std::error_code error_;
};

// What says that a file changed: modification time to the nanosecond, size
// and inode (an editor that saves by renaming a new file over the old one
// changes the inode, maybe nothing else). Links are followed.
struct FileStamp {
    bool exists = false;
    long long mtimeNs = 0;
    long long size = 0;
    unsigned long long inode = 0;
    bool operator==(const FileStamp& o) const {
        return exists == o.exists && mtimeNs == o.mtimeNs && size == o.size && inode == o.inode;
    }
    bool operator!=(const FileStamp& o) const { return !(*this == o); }
};
FileStamp fileStamp(const std::filesystem::path& file);

}  // namespace rl
