// The pool of child processes (see process_pool.h): fork, a pipe per child,
// waitpid without blocking, SIGTERM forwarded on Ctrl-C, SIGKILL at the
// deadline, RLIMIT_CPU and RLIMIT_AS in the child.
#include "core/process_pool.h"

#include "core/child_work.h"
#include "core/error.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <new>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace rl {

namespace {

// A worker whose parent is killed outright (SIGKILL: no handler runs) ends
// too, instead of grading on as an orphan that holds OUT's lock (Linux; the
// check of getppid() covers a parent that died before the prctl).
void dieWithParent(pid_t parent) {
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    if (getppid() != parent) _exit(127);
}

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t gInterrupted = 0;

// In the calling process: only the flag (no new child starts; the loop below
// forwards SIGTERM to the running ones).
extern "C" void onRunInterrupt(int) { gInterrupted = 1; }

// In a child: the flag, and the runIsolated child it waits for is killed at
// once (only async-signal-safe calls: kill).
extern "C" void onChildInterrupt(int) {
    int savedErrno = errno;
    gInterrupted = 1;
    stopIsolatedChild();
    errno = savedErrno;
}

void handleInterrupts(void (*handler)(int), struct sigaction* oldInt, struct sigaction* oldTerm) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, oldInt);
    sigaction(SIGTERM, &sa, oldTerm);
}

struct RunHandlers {  // the caller's handlers are back on every way out
    struct sigaction oldInt {}, oldTerm {};
    RunHandlers() { handleInterrupts(onRunInterrupt, &oldInt, &oldTerm); }
    ~RunHandlers() {
        sigaction(SIGINT, &oldInt, nullptr);
        sigaction(SIGTERM, &oldTerm, nullptr);
    }
};

// From SIGTERM to SIGKILL at a child's deadline: the handler needs
// microseconds; 2 s covers a machine loaded with llvmpipe's threads.
constexpr std::chrono::seconds kKillGrace{2};

[[noreturn]] void childMain(const std::function<std::string(std::size_t)>& work, std::size_t job,
                            const PoolLimits& limits, int fd) {
    handleInterrupts(onChildInterrupt, nullptr, nullptr);
    if (limits.cpuSeconds > 0) {
        rlim_t cpu = rlim_t(limits.cpuSeconds);
        struct rlimit limit {cpu, cpu + 10};
        setrlimit(RLIMIT_CPU, &limit);
    }
    finishChild([&] { return work(job); }, limits.memoryBytes, fd);
}

// Appends what the pipe holds now; false once it is closed (end of file or an error).
bool drain(int fd, std::string& output) {
    char buffer[65536];
    for (;;) {
        ssize_t n = read(fd, buffer, sizeof buffer);
        if (n > 0) {
            output.append(buffer, std::size_t(n));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
    }
}

struct Running {
    std::size_t job = 0;
    int fd = -1;               // the pipe's reading end, -1 once it is closed
    Clock::time_point start, deadline;
    std::string output;
    bool told = false;         // SIGTERM at the deadline
    Clock::time_point killAt;  // then SIGKILL, if it is still there
};

IsolatedResult resultOf(Running& r, int status, const PoolLimits& limits) {
    IsolatedResult result;
    const auto now = Clock::now();
    result.seconds = std::chrono::duration<double>(now - r.start).count();
    const bool marked = !r.output.empty() && r.output[0] == kChildErrorMark;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !marked) {
        result.output = std::move(r.output);
        return result;
    }
    if (gInterrupted) {
        result.outcome = IsolatedResult::Outcome::Interrupted;
        result.reason = "interrupted";
    } else if (r.told || now > r.deadline) {
        result.outcome = IsolatedResult::Outcome::TimedOut;
        char text[64];
        std::snprintf(text, sizeof text, "timed out after %.0f s", limits.deadlineSeconds);
        result.reason = text;
    } else if (marked) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = r.output.substr(1);
    } else if (WIFSIGNALED(status)) {
        result.outcome = IsolatedResult::Outcome::Crashed;
        int sig = WTERMSIG(status);
        result.reason = "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == kChildOutOfMemoryStatus) {
        result.outcome = IsolatedResult::Outcome::OutOfMemory;
        result.reason = "ran out of memory";
    } else {
        result.outcome = IsolatedResult::Outcome::Crashed;
        result.reason = "exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status);
    }
    return result;
}

}  // namespace

bool interruptRequested() { return gInterrupted != 0; }

bool runInPool(std::size_t count, const std::function<std::string(std::size_t)>& work,
               const std::function<void(std::size_t, const IsolatedResult&)>& done, const PoolLimits& limits) {
    gInterrupted = 0;
    RunHandlers handlers;
    std::map<pid_t, Running> running;
    struct CloseAll {  // the pipes of children still running when a done() or a fork throws
        std::map<pid_t, Running>& running;
        ~CloseAll() {
            for (auto& [pid, r] : running)
                if (r.fd >= 0) close(r.fd);
        }
    } closeAll{running};
    const int jobs = std::max(1, limits.jobs);
    const auto never = Clock::time_point::max();
    std::size_t next = 0;
    bool forwarded = false;
    while ((next < count && !gInterrupted) || !running.empty()) {
        while (!gInterrupted && int(running.size()) < jobs && next < count) {
            const std::size_t job = next++;
            int fds[2];
            if (pipe(fds) != 0) throw Error("cannot start " + limits.childName + ": " + std::strerror(errno));
            std::fflush(nullptr);  // nothing buffered is written twice
            const pid_t parent = getpid();
            pid_t pid = fork();
            if (pid < 0) {
                int err = errno;
                close(fds[0]);
                close(fds[1]);
                throw Error("cannot start " + limits.childName + ": " + std::strerror(err));
            }
            if (pid == 0) {
                dieWithParent(parent);
                close(fds[0]);
                for (auto& [other, r] : running)
                    if (r.fd >= 0) close(r.fd);
                childMain(work, job, limits, fds[1]);
            }
            close(fds[1]);
            fcntl(fds[0], F_SETFL, O_NONBLOCK);
            const auto now = Clock::now();
            Running r;
            r.job = job;
            r.fd = fds[0];
            r.start = now;
            r.deadline = never;
            if (limits.deadlineSeconds > 0)
                r.deadline = now + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(limits.deadlineSeconds));
            running.emplace(pid, std::move(r));
        }
        if (gInterrupted && !forwarded) {
            for (const auto& [pid, r] : running) kill(pid, SIGTERM);
            forwarded = true;
        }
        // Up to 50 ms for output; a child's end is found by waitpid below
        // (a grandchild may hold the pipe open after the child is gone).
        std::vector<pollfd> polled;
        for (const auto& [pid, r] : running)
            if (r.fd >= 0) polled.push_back({r.fd, POLLIN, 0});
        poll(polled.data(), nfds_t(polled.size()), 50);
        for (auto& [pid, r] : running)
            if (r.fd >= 0 && !drain(r.fd, r.output)) {
                close(r.fd);
                r.fd = -1;
            }
        for (auto it = running.begin(); it != running.end();) {
            int status = 0;
            pid_t ended = waitpid(it->first, &status, WNOHANG);
            if (ended == 0 || (ended < 0 && errno == EINTR)) {
                // At the deadline SIGTERM first: a child that still runs its
                // handler kills the runIsolated child it waits for, which
                // would otherwise outlive it (until its RLIMIT_CPU); SIGKILL
                // after the grace period. Reaped, and reported, on a later round.
                Running& r = it->second;
                const auto now = Clock::now();
                if (now > r.deadline && !r.told) {
                    kill(it->first, SIGTERM);
                    r.told = true;
                    r.killAt = now + kKillGrace;
                } else if (r.told && now > r.killAt) {
                    kill(it->first, SIGKILL);
                }
                ++it;
                continue;
            }
            if (ended < 0) status = 0xff00;  // reaped elsewhere: reported as "exited with status 255"
            Running r = std::move(it->second);
            it = running.erase(it);
            if (r.fd >= 0) {
                drain(r.fd, r.output);
                close(r.fd);
            }
            done(r.job, resultOf(r, status, limits));
        }
    }
    const bool interrupted = gInterrupted != 0;
    gInterrupted = 0;
    return interrupted;
}

}  // namespace rl
