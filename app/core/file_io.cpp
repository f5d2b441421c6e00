// Atomic writes and bounded reads (see file_io.h for the contracts).
#include "core/file_io.h"

#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl {

namespace {

// What a non-regular file is, for "not a regular file (a FIFO)".
const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string withWhat(const char* verb, const char* what) {
    return std::string(verb) + (what && *what ? std::string(" ") + what : std::string());
}

// The process's umask, read once (umask() can only be read by setting it).
mode_t processUmask() {
    static const mode_t mask = [] {
        mode_t m = umask(022);
        umask(m);
        return m;
    }();
    return mask;
}

// A link to a file: the file it points to is replaced and the link kept.
fs::path resolveLink(const fs::path& path) {
    std::error_code ec;
    if (fs::symlink_status(path, ec).type() != fs::file_type::symlink) return path;
    fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? path : resolved;
}

class TempFile {  // removes the temporary file unless it was renamed
public:
    TempFile(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    ~TempFile() {
        if (fd_ >= 0) close(fd_);
        if (!path_.empty()) unlink(path_.c_str());
    }
    int& fd() { return fd_; }
    const std::string& path() const { return path_; }
    void renamed() { path_.clear(); }

private:
    std::string path_;
    int fd_ = -1;
};

}  // namespace

std::string byteSizeText(std::uintmax_t bytes) {
    if (bytes >= (std::uintmax_t(1) << 30) && bytes % (std::uintmax_t(1) << 30) == 0)
        return std::to_string(bytes >> 30) + " GiB";
    if (bytes >= (std::uintmax_t(1) << 20) && bytes % (std::uintmax_t(1) << 20) == 0)
        return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

void writeFileAtomic(const fs::path& path, std::string_view content, const WriteOptions& options) {
    const std::string shown = path.string();
    auto fail = [&](const std::string& reason) {
        return Error(shown + ": " + withWhat("cannot write", options.what) + " (" + reason + ")");
    };
    if (path.empty()) throw Error(withWhat("cannot write", options.what) + " (the file name is empty)");
    std::error_code ec;
    fs::path target = resolveLink(path);

    struct stat existing {};
    bool exists = stat(target.c_str(), &existing) == 0;
    if (!exists && errno != ENOENT) throw fail(std::strerror(errno));
    if (exists && !S_ISREG(existing.st_mode))
        throw fail(std::string(kindOf(existing.st_mode)) + ", not a regular file; name a file to write");
    if (target.filename().empty()) throw fail("names a folder, not a file");

    fs::path folder = target.parent_path();
    if (options.createFolders && !folder.empty()) fs::create_directories(folder, ec);

    // Same folder as the target, so the rename never crosses file systems.
    std::string pattern = (folder / ("." + target.filename().string() + ".raylab-XXXXXX")).string();
    if (target.filename().string().size() > 200)  // keep the temporary name within NAME_MAX (255)
        pattern = (folder / ".raylab-XXXXXX").string();
    std::string name = pattern;
    int created = mkostemp(name.data(), O_CLOEXEC);
    if (created < 0) throw fail(std::strerror(errno));
    TempFile temp(name, created);
    // mkostemp creates the file 0600; give it what the target had, or what a new file gets.
    mode_t mode = exists ? (existing.st_mode & 07777) : (0666 & ~processUmask());
    if (fchmod(temp.fd(), mode) != 0) throw fail(std::strerror(errno));

    std::size_t written = 0;
    while (written < content.size()) {
        ssize_t n = write(temp.fd(), content.data() + written, content.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw fail(std::strerror(n < 0 ? errno : EIO));
        written += std::size_t(n);
    }
    // fsync before rename: after a power cut the name points at whole content or the old file.
    if (fsync(temp.fd()) != 0) throw fail(std::strerror(errno));
    int fd = temp.fd();
    temp.fd() = -1;
    if (close(fd) != 0) throw fail(std::strerror(errno));
    if (std::rename(temp.path().c_str(), target.c_str()) != 0) throw fail(std::strerror(errno));
    temp.renamed();
    // The rename itself is durable once the folder is synced; a failure here loses nothing.
    int dir = open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        fsync(dir);
        close(dir);
    }
}

void requireOutputPath(const fs::path& path, const char* what) {
    struct stat existing {};
    fs::path target = resolveLink(path);
    auto fail = [&](const std::string& reason) {
        return Error(path.string() + ": " + withWhat("cannot write", what) + " (" + reason + ")");
    };
    if (path.empty()) throw Error(withWhat("cannot write", what) + " (the file name is empty)");
    if (stat(target.c_str(), &existing) == 0) {
        if (!S_ISREG(existing.st_mode)) throw fail(std::string(kindOf(existing.st_mode)) + ", not a regular file; name a file to write");
    } else if (errno != ENOENT) {
        throw fail(std::strerror(errno));
    }
    // The folder must be there and writable: found now, not after the work is done.
    fs::path folder = target.parent_path();
    if (access(folder.empty() ? "." : folder.c_str(), W_OK | X_OK) != 0) throw fail(std::strerror(errno));
}

std::string readRegularFile(const fs::path& path, std::uintmax_t maxBytes, const char* what) {
    const std::string shown = path.string();
    auto fail = [&](const std::string& reason) {
        return Error(shown + ": " + withWhat("cannot read", what) + " (" + reason + ")");
    };
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
    int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) throw fail(errno == ENOENT ? "not found" : std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { close(fd); }
    } closer{fd};
    struct stat info {};
    if (fstat(fd, &info) != 0) throw fail(std::strerror(errno));
    if (S_ISDIR(info.st_mode)) throw fail("is a directory");
    if (!S_ISREG(info.st_mode)) throw fail(std::string("not a regular file: ") + kindOf(info.st_mode));
    if (std::uintmax_t(info.st_size) > maxBytes) throw fail("larger than " + byteSizeText(maxBytes));

    std::string data;
    data.reserve(std::size_t(info.st_size));
    char buffer[1 << 16];
    for (;;) {
        ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n < 0) throw fail(std::strerror(errno));
        if (n == 0) break;
        // The file may grow after fstat: the bound holds for what is read.
        if (data.size() + std::size_t(n) > maxBytes) throw fail("larger than " + byteSizeText(maxBytes));
        data.append(buffer, std::size_t(n));
    }
    return data;
}

fs::path privateTempFolder(const std::string& what) {
    // Removes, at a normal exit of the process that made them, the folders it made.
    struct Made {
        pid_t owner = getpid();
        std::vector<fs::path> folders;
        ~Made() {
            if (getpid() != owner) return;
            std::error_code ec;
            for (const fs::path& f : folders) fs::remove_all(f, ec);
        }
    };
    static Made made;
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) base = "/tmp";
    std::string name = (base / ("raylab-" + what + "-XXXXXX")).string();
    if (!mkdtemp(name.data())) throw Error(name + ": cannot make a temporary folder (" + std::strerror(errno) + ")");
    made.folders.push_back(name);
    return name;
}

}  // namespace rl
