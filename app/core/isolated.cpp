#include "core/isolated.h"

#include "core/child_work.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>

#include <fcntl.h>
#include <spawn.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

extern char** environ;

namespace rl {

namespace {

// The phase note (setIsolatedPhase): one page shared between runIsolated and
// its child, mapped before the fork, read after the child ended.
constexpr std::size_t kPhaseBytes = 256;
char* gPhase = nullptr;

// The child runIsolated waits for, for stopIsolatedChild (a signal handler).
volatile std::sig_atomic_t gChild = 0;

}  // namespace

void setIsolatedPhase(const std::string& phase) {
    if (!gPhase) return;
    std::snprintf(gPhase, kPhaseBytes, "%s", phase.c_str());
}

void stopIsolatedChild() {
    pid_t pid = pid_t(gChild);
    if (pid <= 0) return;
    kill(-pid, SIGKILL);  // its process group: every helper it started
    kill(pid, SIGKILL);   // and itself, should it not have its own group yet
}

bool runProgram(const std::vector<std::string>& args) {
    if (args.empty()) return false;
    std::vector<std::string> copies = args;
    std::vector<char*> argv;
    for (auto& a : copies) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

IsolatedResult runIsolated(const std::function<std::string()>& work, const IsolationLimits& limits) {
    IsolatedResult result;
    int fds[2];
    if (pipe(fds) != 0) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = std::string("cannot create a pipe: ") + std::strerror(errno);
        return result;
    }
    void* shared = mmap(nullptr, kPhaseBytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    gPhase = shared == MAP_FAILED ? nullptr : static_cast<char*>(shared);
    struct Unmap {  // the parent's side of the page, on every way out
        ~Unmap() {
            if (gPhase) munmap(gPhase, kPhaseBytes);
            gPhase = nullptr;
        }
    } unmap;
    auto start = std::chrono::steady_clock::now();
    const pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = std::string("cannot fork: ") + std::strerror(errno);
        return result;
    }
    if (pid == 0) {  // child
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // ends with a parent killed outright (raylab grade's worker)
#endif
        if (getppid() != parent) _exit(127);
        close(fds[0]);
        setpgid(0, 0);  // its own process group, so a timeout kills every thread and helper
        finishChild(work, limits.memoryBytes, fds[1]);
    }
    setpgid(pid, pid);  // also here, so that a kill right after the fork finds the group
    gChild = pid;
    close(fds[1]);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    bool timedOut = false;
    char buffer[65536];
    for (;;) {
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        double left = limits.timeoutSeconds - elapsed;
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        int ready = poll(&p, 1, int(std::min(left, 0.5) * 1000) + 1);
        if (ready > 0) {
            ssize_t n = read(fds[0], buffer, sizeof buffer);
            if (n > 0) {
                result.output.append(buffer, std::size_t(n));
                continue;
            }
            if (n == 0) break;  // child closed the pipe
        }
    }
    if (timedOut) {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
    }
    close(fds[0]);
    gChild = 0;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (gPhase) result.phase.assign(gPhase, strnlen(gPhase, kPhaseBytes));
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (timedOut) {
        result.outcome = IsolatedResult::Outcome::TimedOut;
        char text[64];
        std::snprintf(text, sizeof text, "timed out after %.0f s", limits.timeoutSeconds);
        result.reason = text;
        result.output.clear();
    } else if (WIFSIGNALED(status)) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        int sig = WTERMSIG(status);
        result.reason = std::string("crashed (signal ") + std::to_string(sig) + ", " + strsignal(sig) + ")";
        result.output.clear();
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == kChildOutOfMemoryStatus) {
        result.outcome = IsolatedResult::Outcome::OutOfMemory;
        result.reason = "ran out of memory";
        result.output.clear();
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = "exited with status " + std::to_string(WEXITSTATUS(status));
        result.output.clear();
    } else if (!result.output.empty() && result.output[0] == kChildErrorMark) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = result.output.substr(1);
        result.output.clear();
    }
    return result;
}

}  // namespace rl
