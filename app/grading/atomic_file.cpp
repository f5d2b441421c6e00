#include "grading/atomic_file.h"

#include "core/error.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl {

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
