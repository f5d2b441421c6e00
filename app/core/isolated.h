// Child processes, behind one interface: the only file of raylab's core and
// commands that calls POSIX process functions (fork, pipe, waitpid, kill,
// setrlimit, posix_spawn). app/grading/grade_run.cpp still runs its own
// worker pool (docs/decisions.md, "Child processes on macOS and Windows").
//
// runIsolated: a piece of work in a child process with a wall-clock timeout
// and a memory limit, so that user code (a student's shader that loops
// forever, exhausts memory or crashes the driver) costs that piece of work,
// never the caller. The child's result comes back as text through a pipe.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rl {

struct IsolationLimits {
    double timeoutSeconds = 20;
    std::size_t memoryBytes = std::size_t(6) << 30;  // address space; llvmpipe reserves ~1-2 GiB of it
};

struct IsolatedResult {
    enum class Outcome { Finished, TimedOut, Crashed, OutOfMemory } outcome = Outcome::Finished;
    std::string output;   // what the work returned (Finished only)
    std::string reason;   // "timed out after 20 s", "killed by signal 11 (SIGSEGV)", ...
    double seconds = 0;
};

// Forks; the child runs `work` (which must not need the parent's GL context:
// create a new one) and exits. Needs no threads running in the parent.
IsolatedResult runIsolated(const std::function<std::string()>& work, const IsolationLimits& limits);

// Runs a program (args[0], looked up on PATH) with this process's standard
// streams and waits for it. True when it started and exited with status 0.
bool runProgram(const std::vector<std::string>& args);

}  // namespace rl
