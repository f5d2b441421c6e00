// The pool of child processes (core/process_pool.h) and runIsolated's phase
// note (core/isolated.h): every outcome a grading worker can have, with
// children that sleep or spin for at most a few seconds.
#include "core/isolated.h"
#include "core/process_pool.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <cstdlib>
#include <map>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using namespace rl;
using Outcome = IsolatedResult::Outcome;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::map<std::size_t, IsolatedResult> runAll(std::size_t count, const std::function<std::string(std::size_t)>& work,
                                             const PoolLimits& limits, bool* interrupted = nullptr) {
    std::map<std::size_t, IsolatedResult> results;
    bool stopped = runInPool(count, work, [&](std::size_t k, const IsolatedResult& r) { results[k] = r; }, limits);
    if (interrupted) *interrupted = stopped;
    return results;
}

}  // namespace

TEST(ProcessPool, EachOutcomeWithItsReason) {
    PoolLimits limits;
    limits.jobs = 3;
    limits.deadlineSeconds = 1;
    auto work = [](std::size_t k) -> std::string {
        switch (k) {
            case 0: return "student 0 done";
            case 1: throw std::runtime_error("OUT cannot be written");
            case 2: throw ChildExit{2};
            case 3: std::abort();
            case 4: throw std::bad_alloc();
            default: std::this_thread::sleep_for(std::chrono::seconds(20)); return "too late";
        }
    };
    auto start = Clock::now();
    bool interrupted = true;
    auto results = runAll(6, work, limits, &interrupted);
    EXPECT_FALSE(interrupted);
    ASSERT_EQ(results.size(), 6u);
    EXPECT_EQ(results[0].outcome, Outcome::Finished);
    EXPECT_EQ(results[0].output, "student 0 done");
    EXPECT_EQ(results[1].outcome, Outcome::Crashed);
    EXPECT_EQ(results[1].reason, "OUT cannot be written");
    EXPECT_EQ(results[2].outcome, Outcome::Crashed);
    EXPECT_EQ(results[2].reason, "exited with status 2");  // grade_run: "worker exited with status 2"
    EXPECT_EQ(results[3].outcome, Outcome::Crashed);
    EXPECT_EQ(results[3].reason, "killed by signal 6 (Aborted)");  // "worker killed by signal 6 (Aborted)"
    EXPECT_EQ(results[4].outcome, Outcome::OutOfMemory);
    EXPECT_EQ(results[5].outcome, Outcome::TimedOut);
    EXPECT_EQ(results[5].reason, "timed out after 1 s");
    // The sleeper is killed at its 1 s deadline, not after its 20 s.
    EXPECT_LT(secondsSince(start), 10.0);
    EXPECT_FALSE(interruptRequested());
}

TEST(ProcessPool, AtMostJobsChildrenAtATimeAndLargeOutputsArrive) {
    PoolLimits limits;
    limits.jobs = 2;
    // Each child says when it ran; two at a time means no three overlap.
    auto work = [](std::size_t k) {
        auto from = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        auto to = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
        std::string big(k == 0 ? 300000 : 0, 'x');  // over a pipe's 64 KiB: read while the child writes
        return std::to_string(from) + " " + std::to_string(to) + " " + big;
    };
    auto results = runAll(5, work, limits);
    ASSERT_EQ(results.size(), 5u);
    std::vector<std::pair<double, double>> spans;
    for (auto& [k, r] : results) {
        ASSERT_EQ(r.outcome, Outcome::Finished) << r.reason;
        double from = std::stod(r.output), to = std::stod(r.output.substr(r.output.find(' ') + 1));
        spans.push_back({from, to});
        if (k == 0) EXPECT_EQ(r.output.size() - r.output.rfind(' ') - 1, 300000u);
    }
    // The most running at once is the most running at some child's start.
    for (auto& s : spans) {
        int running = 0;
        for (auto& o : spans) running += o.first <= s.first && s.first < o.second;
        EXPECT_LE(running, 2);  // itself and at most one other
    }
}

TEST(ProcessPool, TheCpuAndMemoryLimitsHoldInTheChild) {
    PoolLimits limits;
    limits.cpuSeconds = 1;
    limits.memoryBytes = std::size_t(512) << 20;
    auto work = [](std::size_t k) -> std::string {
        if (k == 0) {
            volatile unsigned long spin = 0;
            for (;;) spin = spin + 1;  // SIGXCPU after 1 s of CPU time
        }
        std::vector<char> huge(std::size_t(4) << 30, 1);  // over the address-space limit
        return std::to_string(huge[12345]);
    };
#ifdef __SANITIZE_ADDRESS__  // no address-space limit there (process_pool.cpp): the 4 GiB would be allocated
    auto results = runAll(1, work, limits);
#else
    auto results = runAll(2, work, limits);
#endif
    EXPECT_EQ(results[0].outcome, Outcome::Crashed);
    EXPECT_EQ(results[0].reason, "killed by signal 24 (CPU time limit exceeded)");
#ifndef __SANITIZE_ADDRESS__  // no address-space limit under AddressSanitizer (process_pool.cpp)
    EXPECT_EQ(results[1].outcome, Outcome::OutOfMemory) << results[1].reason;
#endif
}

// Ctrl-C during a run: no new child starts, the running ones are told,
// stop the runIsolated child they wait for at once (not at its 30 s timeout)
// and end; the run says it was interrupted, and the caller's handler is back.
TEST(ProcessPool, CtrlCStopsTheRunningChildrenAndTheirChecksAtOnce) {
    PoolLimits limits;
    limits.jobs = 2;
    auto work = [](std::size_t) -> std::string {
        IsolationLimits checkLimits;
        checkLimits.timeoutSeconds = 30;
        IsolatedResult check = runIsolated(
            [] {
                std::this_thread::sleep_for(std::chrono::seconds(30));
                return std::string("a check that was not stopped");
            },
            checkLimits);
        if (interruptRequested()) throw ChildExit{130};
        return check.output;
    };
    std::thread ctrlC([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        std::raise(SIGINT);  // to the process: its pool handler takes it, on whichever thread
    });
    auto start = Clock::now();
    bool interrupted = false;
    auto results = runAll(5, work, limits, &interrupted);
    ctrlC.join();
    EXPECT_TRUE(interrupted);
    EXPECT_LT(secondsSince(start), 15.0) << "the checks ran to their timeout";
    EXPECT_EQ(results.size(), 2u) << "no child starts after Ctrl-C";
    for (auto& [k, r] : results) EXPECT_EQ(r.outcome, Outcome::Interrupted) << k << ": " << r.reason;
    EXPECT_FALSE(interruptRequested());
    struct sigaction now {};
    sigaction(SIGINT, nullptr, &now);
    EXPECT_EQ(now.sa_handler, SIG_DFL) << "the caller's handler is back";
}

// A child stopped at its deadline takes the runIsolated child it waits for
// with it: that one would write a file 3 s after it started, and does not.
TEST(ProcessPool, AChildStoppedAtItsDeadlineLeavesNoOrphan) {
    const fs::path marker = rl::test::freshTempDir("pool_orphan") / "the orphan ran on";
    PoolLimits limits;
    limits.deadlineSeconds = 0.5;
    auto work = [&](std::size_t) -> std::string {
        IsolationLimits checkLimits;
        checkLimits.timeoutSeconds = 30;
        runIsolated(
            [&] {
                std::this_thread::sleep_for(std::chrono::seconds(3));
                rl::test::writeText(marker, "it outlived its worker");
                return std::string();
            },
            checkLimits);
        if (interruptRequested()) throw ChildExit{130};
        return "the check ended by itself";
    };
    auto start = Clock::now();
    auto results = runAll(1, work, limits);
    EXPECT_EQ(results[0].outcome, Outcome::TimedOut) << results[0].reason;
    EXPECT_LT(secondsSince(start), 2.5) << "stopped at the deadline, not after the check";
    std::this_thread::sleep_for(std::chrono::duration<double>(4.0 - secondsSince(start)));
    EXPECT_FALSE(fs::exists(marker)) << "the check outlived its worker";
}

TEST(Isolated, ThePhaseNoteSaysWhatTheChildWasDoingWhenItTimedOut) {
    IsolationLimits limits;
    limits.timeoutSeconds = 1;
    IsolatedResult r = runIsolated(
        [] {
            setIsolatedPhase("compiling");
            setIsolatedPhase("rendering scene 3");
            std::this_thread::sleep_for(std::chrono::seconds(20));
            return std::string();
        },
        limits);
    EXPECT_EQ(r.outcome, Outcome::TimedOut);
    EXPECT_EQ(r.phase, "rendering scene 3");
    setIsolatedPhase("outside a child: nothing happens");
    IsolatedResult quiet = runIsolated([] { return std::string("ok"); }, limits);
    EXPECT_EQ(quiet.outcome, Outcome::Finished);
    EXPECT_EQ(quiet.output, "ok");
    EXPECT_EQ(quiet.phase, "");
}
