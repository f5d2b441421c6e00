// The fuzzer's machinery (tests/fuzz/test_fuzz.cpp): seeds, a time budget, a
// sandbox folder, running raylab with a timeout, and the promise checked on
// every run.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace rl::fuzz {

// RAYLAB_FUZZ_SEED, RAYLAB_FUZZ_COUNT, RAYLAB_FUZZ_SECONDS, RAYLAB_FUZZ_RUN_TIMEOUT,
// RAYLAB_FUZZ_AFTER_DIAGNOSTICS (see test_fuzz.cpp).
struct Settings {
    std::uint64_t seed = 20261201;  // the suite's fixed seed set
    long count = 0;                 // inputs per test; 0: each test's default
    double seconds = 30;            // time budget per test (2 cores, llvmpipe: about 2 minutes for the label)
    double runTimeout = 60;         // one raylab run; a render of 16x12 takes well under a second
    bool afterDiagnostics = false;  // RAYLAB_FUZZ_AFTER_DIAGNOSTICS=1 (see test_fuzz.cpp)
    static Settings fromEnvironment();
};

// splitmix64 over a seed made of (suite seed, test, input number): each input
// can be rebuilt alone from the seed printed with a failure.
class Rng {
public:
    Rng(std::uint64_t seed, const std::string& test, std::uint64_t index);
    std::uint64_t next();
    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(next() % n); }
    template <typename T>
    T pick(std::initializer_list<T> items) {
        return *(items.begin() + below(items.size()));
    }
    std::uint64_t seed() const { return seed_; }

private:
    std::uint64_t seed_, state_;
};

// Counts inputs against RAYLAB_FUZZ_COUNT (or the test's default) and the time budget.
class Budget {
public:
    Budget(const Settings& settings, long defaultCount);
    bool next();
    void report(const std::string& what) const;

private:
    const Settings& settings_;
    long target_, done_ = 0;
    double start_;
    bool outOfTime_ = false;
};

// A fresh folder under $TMPDIR, removed afterwards unless a check failed there.
class Sandbox {
public:
    Sandbox();
    ~Sandbox();
    Sandbox(const Sandbox&) = delete;
    Sandbox& operator=(const Sandbox&) = delete;
    const std::filesystem::path& dir() const { return dir_; }
    void write(const std::string& relative, const std::string& content);
    // kind: fifo, dir, device (a scratch /dev/null node, root only), link-to-dir,
    // link-loop, dangling, empty, unreadable. False when it cannot be made here.
    bool makeSpecial(const std::string& relative, const std::string& kind);
    void keep(const std::string& why);  // copies the folder to $TMPDIR/raylab_fuzz_failures/

private:
    std::filesystem::path dir_;
};

struct Invocation {
    std::vector<std::string> args;
    std::vector<std::string> outputs;  // files the command names as outputs (relative)
    std::string outputFolder;          // a folder the command writes into (grade -o): everything under it is output
    std::vector<std::string> culprits;  // the error line must name one of them (none: anything)
    std::string description;           // for failure messages
    std::uint64_t seed = 0;
    bool mayPass = true;          // the input may be valid: exit 0 is then fine
    bool lenientMessage = false;  // shader folders before the diagnostics merge (see test_fuzz.cpp)
    // A shader error, printed as compilers print one: the first line is
    // raylab's error naming the student's file and line; each later line is
    // that source line (indented), another diagnostic of the same files, or
    // the count of those left out (at most 10 are printed).
    bool compilerDiagnostics = false;
};

// Runs raylab in the sandbox and checks the promise with GoogleTest assertions.
void expectPromise(Sandbox& box, const Invocation& run, const Settings& settings);

std::filesystem::path sourceRoot();
std::string readFile(const std::filesystem::path& path);

}  // namespace rl::fuzz
