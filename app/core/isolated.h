// Child processes, behind one interface: isolated.h (one piece of work in a
// child, one program run) and process_pool.h (many pieces of work, `jobs` at
// a time, with Ctrl-C handling) are the only headers through which raylab
// starts, limits, signals or waits for a process. Their two .cpp files are
// the only files of app/ that call POSIX process functions (fork, pipe,
// waitpid, kill, sigaction, setrlimit, posix_spawn, mmap);
// tests/unit/test_architecture.cpp fails if another file does. What a macOS
// and a Windows port must implement, function by function: docs/decisions.md,
// "Child processes on macOS and Windows".
//
// runIsolated: a piece of work in a child process with a wall-clock timeout
// and a memory limit, so that user code (a student's shader that loops
// forever, exhausts memory or crashes the driver) costs that piece of work,
// never the caller. The child's result comes back as text through a pipe.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rl {

struct IsolationLimits {
    double timeoutSeconds = 20;
    std::size_t memoryBytes = std::size_t(6) << 30;  // address space; llvmpipe reserves ~1-2 GiB of it
};

struct IsolatedResult {
    // Interrupted: only from runInPool (process_pool.h), a child that did not
    // finish because the run was interrupted (Ctrl-C, SIGTERM).
    enum class Outcome { Finished, TimedOut, Crashed, OutOfMemory, Interrupted } outcome = Outcome::Finished;
    std::string output;   // what the work returned (Finished only)
    std::string reason;   // "timed out after 20 s", "crashed (signal 11, Segmentation fault)", ...
    std::string phase;    // the last setIsolatedPhase() of the child before it ended ("" if none)
    double seconds = 0;
};

// Forks; the child runs `work` (which must not need the parent's GL context:
// create a new one) in its own process group and exits; on timeout the whole
// group is killed. Needs no threads running in the parent. A std::exception
// out of `work` is Crashed with its message as the reason; std::bad_alloc
// (or the address-space limit) is OutOfMemory.
IsolatedResult runIsolated(const std::function<std::string()>& work, const IsolationLimits& limits);

// Called in runIsolated's child: a short note of what the work is doing now
// ("compiling", "rendering scene-3"), kept in memory shared with the parent,
// so that a child killed on timeout still says what ran out of time
// (IsolatedResult::phase). At most 255 bytes are kept. Does nothing outside
// a runIsolated child (the same work run in-process).
void setIsolatedPhase(const std::string& phase);

// Async-signal-safe: kills the process group of the runIsolated child this
// process is waiting for, if any (runIsolated then reports it Crashed). The
// pool's workers call it on Ctrl-C (process_pool.h).
void stopIsolatedChild();

// Runs a program (args[0], looked up on PATH) with this process's standard
// streams and waits for it. True when it started and exited with status 0.
bool runProgram(const std::vector<std::string>& args);

}  // namespace rl
