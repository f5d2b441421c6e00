#include "grading/atomic_file.h"

#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl {

void writeFileAtomic(const fs::path& path, const std::string& content) {
    std::error_code ec;
    if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
    // The pid keeps parallel workers (and a concurrent shard) off each other's temporary files.
    fs::path temp = path;
    temp += ".tmp-" + std::to_string(getpid());
    int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
    std::size_t written = 0;
    while (written < content.size()) {
        ssize_t n = write(fd, content.data() + written, content.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            int err = errno;
            close(fd);
            fs::remove(temp, ec);
            throw Error(path.string() + ": cannot write (" + std::strerror(err) + ")");
        }
        written += std::size_t(n);
    }
    // fsync before rename: after a power cut the name points at whole content or the old file.
    if (fsync(fd) != 0 || close(fd) != 0) {
        int err = errno;
        fs::remove(temp, ec);
        throw Error(path.string() + ": cannot write (" + std::strerror(err) + ")");
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        int err = errno;
        fs::remove(temp, ec);
        throw Error(path.string() + ": cannot write (" + std::strerror(err) + ")");
    }
}

std::string readWholeFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot read (" + std::strerror(errno) + ")");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

FolderLock::FolderLock(const fs::path& folder) {
    fs::path path = folder / ".lock";
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw Error(path.string() + ": cannot create (" + std::strerror(errno) + ")");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        close(fd_);
        throw Error(folder.string() + ": another raylab grade is writing here; wait for it, or use another -o");
    }
}

FolderLock::~FolderLock() {
    if (fd_ >= 0) close(fd_);  // releases the lock
}

bool pathsOverlap(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    fs::path x = fs::weakly_canonical(fs::absolute(a, ec), ec), y = fs::weakly_canonical(fs::absolute(b, ec), ec);
    auto inside = [](const fs::path& p, const fs::path& folder) {
        auto rel = p.lexically_relative(folder);
        return !rel.empty() && *rel.begin() != "..";
    };
    return inside(x, y) || inside(y, x);
}

}  // namespace rl
