// A pool of child processes: `count` pieces of work, each in its own child,
// `jobs` at a time, each with a wall-clock deadline, a CPU-time limit and an
// address-space limit, and Ctrl-C handled for the whole run. The second half
// of the child-process interface (core/isolated.h has the first, and says
// what a macOS or Windows port must implement).
//
// Ctrl-C (SIGINT) or SIGTERM while runInPool runs only sets a flag in the
// calling process: no new child starts, each running child is sent SIGTERM,
// and runInPool waits for all of them and returns true. In a child, the same
// signals set the flag that interruptRequested() reads and kill the
// process group of the runIsolated child it waits for, if any
// (stopIsolatedChild), so the work can end at once instead of at that
// child's timeout. The previous handlers are back when runInPool returns.
#pragma once

#include "core/isolated.h"

#include <cstddef>
#include <functional>
#include <string>

namespace rl {

struct PoolLimits {
    int jobs = 1;                 // children running at the same time
    // Wall clock per child from its start, then SIGTERM (the child's handler
    // kills the runIsolated child it waits for) and SIGKILL 2 s later; 0: none.
    double deadlineSeconds = 0;
    // CPU time per child (RLIMIT_CPU, inherited by its own children, so even
    // a grandchild orphaned by a killed child ends): SIGXCPU at the limit,
    // SIGKILL 10 s later. 0: none.
    double cpuSeconds = 0;
    std::size_t memoryBytes = 0;  // address space per child (not under AddressSanitizer); 0: none
    std::string childName = "a child process";  // for "cannot start a grading worker: <reason>"
};

// Runs work(0) ... work(count - 1), each in a forked child (which must not
// need a GL context of the caller's, and should not find threads running in
// it), in that order, at most limits.jobs at a time, and calls
// done(k, result) in the calling process as each child ends, in the order
// they end. result.outcome is:
//   Finished     the work returned; result.output is what it returned
//   TimedOut     stopped at the deadline (or ended otherwise after it)
//   Crashed      reason "killed by signal 9 (Killed)", "exited with status 2"
//                (see ChildExit), or the message of a std::exception out of work
//   OutOfMemory  std::bad_alloc out of work (or the address-space limit)
//   Interrupted  it did not finish because the run was interrupted
// Returns whether the run was interrupted. Throws rl::Error
// "cannot start <childName>: <reason>" when a child cannot be started.
bool runInPool(std::size_t count, const std::function<std::string(std::size_t)>& work,
               const std::function<void(std::size_t, const IsolatedResult&)>& done, const PoolLimits& limits);

// Thrown by work in a pool's child: the child exits with this status at once
// (done sees Crashed, "exited with status N"; 0 is Finished with no output).
struct ChildExit {
    int status;
};

// In a pool's child: whether Ctrl-C or SIGTERM arrived (the work should stop
// and throw ChildExit). In the calling process, during runInPool: the same
// for the run. False elsewhere.
bool interruptRequested();

}  // namespace rl
