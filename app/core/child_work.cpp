#include "core/child_work.h"

#include "core/process_pool.h"

#include <cerrno>
#include <cstdio>
#include <exception>
#include <new>

#include <sys/resource.h>
#include <unistd.h>

namespace rl {

void finishChild(const std::function<std::string()>& work, std::size_t memoryBytes, int fd) {
#ifndef __SANITIZE_ADDRESS__
    if (memoryBytes > 0) {
        struct rlimit limit;
        limit.rlim_cur = limit.rlim_max = rlim_t(memoryBytes);
        setrlimit(RLIMIT_AS, &limit);
    }
#else
    (void)memoryBytes;
#endif
    std::string out;
    int status = 0;
    try {
        out = work();
    } catch (const ChildExit& e) {
        status = e.status;
    } catch (const std::bad_alloc&) {
        status = kChildOutOfMemoryStatus;
    } catch (const std::exception& e) {
        out = std::string(1, kChildErrorMark) + e.what();
    } catch (...) {
        out = std::string(1, kChildErrorMark) + "an unknown exception";
    }
    std::size_t written = 0;
    while (written < out.size()) {
        ssize_t n = write(fd, out.data() + written, out.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        written += std::size_t(n);
    }
    close(fd);
    std::fflush(nullptr);
    _exit(status);
}

}  // namespace rl
