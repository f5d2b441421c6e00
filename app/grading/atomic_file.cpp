#include "grading/atomic_file.h"

#include "core/error.h"

namespace fs = std::filesystem;

namespace rl {

FolderLock::FolderLock(const fs::path& folder) : lock_(folder / ".lock") {
    if (lock_.error()) throw Error((folder / ".lock").string() + ": cannot create (" + lock_.error().message() + ")");
    // A run killed outright releases the lock when the last of its workers
    // and their check processes has ended: they end with it (PR_SET_PDEATHSIG),
    // but tearing down a GL context takes a moment on a loaded machine, so a
    // run started right after waits that long before it says so.
    if (!lock_.held() && !lock_.waitFor(3.0))
        throw Error(folder.string() + ": another raylab grade is writing here; wait for it, or use another -o");
}

FolderLock::~FolderLock() = default;  // the lock goes with lock_

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
