#include "fuzz/fuzz_support.h"

#include "core/image.h"
#include "core/paths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl::fuzz {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    return h;
}

// What a file is, for the before/after comparison: type, mode, and content
// (or device number, or link target). Never follows links, never opens a FIFO.
std::map<std::string, std::string> snapshot(const fs::path& root) {
    std::map<std::string, std::string> out;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
         it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const fs::path& p = it->path();
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0) continue;
        std::string sig = std::to_string(st.st_mode);
        if (S_ISREG(st.st_mode)) {
            int fd = open(p.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
            std::uint64_t h = 1469598103934665603ull;
            if (fd >= 0) {
                char buffer[1 << 16];
                ssize_t n;
                while ((n = read(fd, buffer, sizeof buffer)) > 0) h = fnv1a(std::string(buffer, std::size_t(n)), h);
                close(fd);
            }
            sig += " size " + std::to_string(st.st_size) + " hash " + std::to_string(h);
        } else if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) {
            sig += " dev " + std::to_string(st.st_rdev);
        } else if (S_ISLNK(st.st_mode)) {
            sig += " -> " + fs::read_symlink(p, ec).string();
        }
        out[p.lexically_relative(root).string()] = sig;
        if (S_ISLNK(st.st_mode)) it.disable_recursion_pending();
    }
    return out;
}

struct RunResult {
    bool timedOut = false;
    int status = -1;  // exit status, or -1 with a signal
    int signal = 0;
    std::string out, err;
    double seconds = 0;
};

RunResult runRaylab(const fs::path& dir, const std::vector<std::string>& args, double timeout) {
    RunResult r;
    // Captured outside the sandbox, so they are not part of its before/after comparison.
    char outName[] = "/tmp/raylab_fuzz_out_XXXXXX";
    char errName[] = "/tmp/raylab_fuzz_err_XXXXXX";
    int outFd = mkstemp(outName), errFd = mkstemp(errName);
    double start = now();
    pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);  // its own group: a timeout kills raylab's children (check's workers) too
        if (chdir(dir.c_str()) != 0) _exit(126);
        // Under the asan preset: raylab's own memory errors and undefined behaviour still end the
        // run with a report (a signal-free non-zero exit and a stderr the checks below refuse), but
        // not LeakSanitizer: llvmpipe leaves 112 bytes allocated at exit from a driver library
        // that is unloaded by then, so the report has no frames a suppression could match
        // (tests/sanitizers/lsan.supp). The unit tests keep leak checking.
        if (const char* asan = std::getenv("ASAN_OPTIONS"))
            setenv("ASAN_OPTIONS", (std::string(asan) + ":detect_leaks=0").c_str(), 1);
        int null = open("/dev/null", O_RDONLY);
        dup2(null, 0);
        dup2(outFd, 1);
        dup2(errFd, 2);
        std::vector<char*> argv;
        std::string binary = RAYLAB_BINARY;
        argv.push_back(binary.data());
        std::vector<std::string> copy = args;
        for (std::string& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    int status = 0;
    for (;;) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (now() - start > timeout) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            r.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    r.seconds = now() - start;
    if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    auto slurp = [](int fd) {
        std::string s;
        lseek(fd, 0, SEEK_SET);
        char buffer[1 << 16];
        ssize_t n;
        while ((n = read(fd, buffer, sizeof buffer)) > 0 && s.size() < (1u << 22)) s.append(buffer, std::size_t(n));
        close(fd);
        return s;
    };
    r.out = slurp(outFd);
    r.err = slurp(errFd);
    unlink(outName);
    unlink(errName);
    return r;
}

std::vector<std::string> linesOf(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

std::string printableForReport(const std::string& s) {
    std::string out;
    for (unsigned char c : s.substr(0, 600)) {
        if (c == '\n') out += "\\n";
        else if (c < 0x20 || c == 0x7f) out += "\\x" + std::string(1, "0123456789abcdef"[c >> 4]) + "0123456789abcdef"[c & 15];
        else out += char(c);
    }
    return s.size() > 600 ? out + "... (" + std::to_string(s.size()) + " bytes)" : out;
}

std::string commandLine(const std::vector<std::string>& args) {
    std::string s = "raylab";
    for (const std::string& a : args) s += " '" + printableForReport(a.substr(0, 60)) + (a.size() > 60 ? "...'" : "'");
    return s;
}

}  // namespace

Settings Settings::fromEnvironment() {
    Settings s;
    if (const char* v = std::getenv("RAYLAB_FUZZ_SEED"); v && *v) s.seed = std::strtoull(v, nullptr, 10);
    if (const char* v = std::getenv("RAYLAB_FUZZ_COUNT"); v && *v) s.count = std::strtol(v, nullptr, 10);
    if (const char* v = std::getenv("RAYLAB_FUZZ_SECONDS"); v && *v) s.seconds = std::strtod(v, nullptr);
    if (const char* v = std::getenv("RAYLAB_FUZZ_RUN_TIMEOUT"); v && *v) s.runTimeout = std::strtod(v, nullptr);
    if (const char* v = std::getenv("RAYLAB_FUZZ_AFTER_DIAGNOSTICS"); v && *v) s.afterDiagnostics = std::string(v) == "1";
    return s;
}

Rng::Rng(std::uint64_t seed, const std::string& test, std::uint64_t index)
    : seed_(fnv1a(test + "/" + std::to_string(seed) + "/" + std::to_string(index))), state_(seed_) {}

std::uint64_t Rng::next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

Budget::Budget(const Settings& settings, long defaultCount)
    : settings_(settings), target_(settings.count > 0 ? settings.count : defaultCount), start_(now()) {}

bool Budget::next() {
    if (done_ >= target_) return false;
    if (now() - start_ > settings_.seconds) {
        outOfTime_ = true;
        return false;
    }
    ++done_;
    return true;
}

void Budget::report(const std::string& what) const {
    std::cout << "fuzz: " << what << ": " << done_ << " of " << target_ << " inputs in " << int(now() - start_ + 0.5)
              << " s, seed " << settings_.seed << (outOfTime_ ? " (time budget used up)" : "") << std::endl;
}

Sandbox::Sandbox() {
    std::string pattern = (fs::temp_directory_path() / "raylab_fuzz_XXXXXX").string();
    dir_ = mkdtemp(pattern.data());
}

Sandbox::~Sandbox() {
    std::error_code ec;
    for (auto& e : fs::recursive_directory_iterator(dir_, ec))
        if (!e.is_symlink(ec)) fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
}

void Sandbox::write(const std::string& relative, const std::string& content) {
    fs::path p = dir_ / relative;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << content;
}

bool Sandbox::makeSpecial(const std::string& relative, const std::string& kind) {
    fs::path p = dir_ / relative;
    std::error_code ec;
    if (kind == "fifo") return mkfifo(p.c_str(), 0600) == 0;
    if (kind == "dir") return fs::create_directory(p, ec);
    if (kind == "device") return mknod(p.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;  // like /dev/null
    if (kind == "link-to-dir") {
        fs::create_directory(dir_ / "linked-folder", ec);
        fs::create_symlink("linked-folder", p, ec);
        return !ec;
    }
    if (kind == "link-loop") {
        fs::create_symlink(relative, p, ec);
        return !ec;
    }
    if (kind == "dangling") {
        fs::create_symlink("nowhere/none", p, ec);
        return !ec;
    }
    if (kind == "empty") {
        write(relative, "");
        return true;
    }
    if (kind == "unreadable") {
        write(relative, readFile(sourceRoot() / "scenes/lecture.json"));
        return chmod(p.c_str(), 0) == 0;
    }
    return false;
}

void Sandbox::keep(const std::string& why) {
    fs::path kept = fs::temp_directory_path() / "raylab_fuzz_failures" / dir_.filename();
    std::error_code ec;
    fs::create_directories(kept, ec);
    fs::copy(dir_, kept, fs::copy_options::recursive | fs::copy_options::copy_symlinks | fs::copy_options::skip_existing,
             ec);
    std::ofstream(kept / "WHY.txt") << why << "\n";
}

void expectPromise(Sandbox& box, const Invocation& run, const Settings& settings) {
    auto before = snapshot(box.dir());
    RunResult r = runRaylab(box.dir(), run.args, settings.runTimeout);
    auto after = snapshot(box.dir());

    std::string context = "seed " + std::to_string(run.seed) + " (" + run.description + "): " + commandLine(run.args) +
                          "\n  exit " + std::to_string(r.status) + (r.signal ? " signal " + std::to_string(r.signal) : "") +
                          ", stderr: " + printableForReport(r.err);
    std::vector<std::string> problems;
    if (r.timedOut) problems.push_back("no answer within " + std::to_string(int(settings.runTimeout)) + " s (hang)");
    else if (r.signal) problems.push_back(std::string("killed by signal ") + strsignal(r.signal) + " (crash)");
    if (r.err.find("Sanitizer") != std::string::npos || r.err.find(": runtime error: ") != std::string::npos)
        problems.push_back("a sanitizer report (asan preset)");
    if (r.err.size() > 20000) problems.push_back("stderr is " + std::to_string(r.err.size()) + " bytes");
    if (!r.timedOut && !r.signal) {
        std::vector<std::string> lines = linesOf(r.err);
        int errors = 0;
        for (const std::string& l : lines) errors += l.rfind("raylab: error: ", 0) == 0;
        if (r.status == 3) problems.push_back("internal error (exit 3)");
        if (r.status == 0 && !run.mayPass) problems.push_back("a bad input was accepted (exit 0)");
        if (r.status != 0 && !run.lenientMessage && run.compilerDiagnostics) {
            if (lines.empty() || lines.front().rfind("raylab: error: ", 0) != 0)
                problems.push_back("stderr does not start with 'raylab: error: '");
            if (errors != 1) problems.push_back(std::to_string(errors) + " lines start with 'raylab: error: '");
            // 10 diagnostics of two lines each, the count of the rest: 22 lines at most.
            if (lines.size() > 22) problems.push_back(std::to_string(lines.size()) + " lines of diagnostics");
            for (std::size_t k = 1; k < lines.size(); ++k) {
                const std::string& l = lines[k];
                bool sourceLine = l.rfind("    ", 0) == 0;
                bool rest = l.rfind("... and ", 0) == 0;
                bool diagnostic = false;
                for (const std::string& c : run.culprits) diagnostic = diagnostic || l.find(c) != std::string::npos;
                if (!sourceLine && !rest && !diagnostic)
                    problems.push_back("a line that is neither a diagnostic nor its source line: " + printableForReport(l));
            }
            bool named = run.culprits.empty();
            for (const std::string& c : run.culprits)
                named = named || (!lines.empty() && lines.front().find(c) != std::string::npos);
            if (!named) problems.push_back("the error does not name " + printableForReport(run.culprits.front()));
        } else if (r.status != 0 && !run.lenientMessage) {
            if (errors != 1) problems.push_back(std::to_string(errors) + " lines start with 'raylab: error: '");
            for (const std::string& l : lines)
                if (l.rfind("raylab: error: ", 0) != 0 && l.rfind("raylab: warning: ", 0) != 0 &&
                    l.rfind("bench: ", 0) != 0)  // bench's progress log, by design on stderr
                    problems.push_back("a line that is neither an error nor a warning: " + printableForReport(l));
            bool named = run.culprits.empty();
            for (const std::string& c : run.culprits)
                named = named || (!lines.empty() && lines.back().find(c) != std::string::npos);
            if (!named) problems.push_back("the error does not name " + printableForReport(run.culprits.front()));
        }
        if (r.status != 0 && run.lenientMessage && !lines.empty() && lines.front().rfind("raylab: error: ", 0) != 0)
            problems.push_back("stderr does not start with 'raylab: error: '");
    }
    // Outputs: a successful run may replace them; a failed one keeps everything.
    for (const std::string& o : run.outputs) {
        if (r.status != 0 || r.signal || r.timedOut) continue;
        before.erase(o);
        after.erase(o);
    }
    if (!run.outputFolder.empty())
        for (auto* files : {&before, &after})
            for (auto it = files->begin(); it != files->end();)
                it = it->first == run.outputFolder || it->first.rfind(run.outputFolder + "/", 0) == 0 ? files->erase(it)
                                                                                                     : std::next(it);
    for (const auto& [path, sig] : after) {
        auto it = before.find(path);
        if (it == before.end()) problems.push_back("new file " + printableForReport(path));
        else if (it->second != sig) problems.push_back("changed " + printableForReport(path));
    }
    for (const auto& [path, sig] : before)
        if (!after.count(path)) problems.push_back("deleted " + printableForReport(path));
    // No NaN or Inf in any radiance written.
    if (r.status == 0)
        for (const std::string& o : run.outputs) {
            std::error_code ec;
            if (fs::path(o).extension() != ".pfm" || !fs::is_regular_file(box.dir() / o, ec)) continue;
            try {
                RadianceImage image = readPfm((box.dir() / o).string());
                long bad = 0;
                for (float v : image.rgb) bad += !std::isfinite(v);
                if (bad) problems.push_back(o + " holds " + std::to_string(bad) + " NaN or Inf values");
            } catch (const std::exception& e) {
                problems.push_back(o + " cannot be read back: " + e.what());
            }
        }
    if (!problems.empty()) {
        std::string all;
        for (const std::string& p : problems) all += "\n  - " + p;
        box.keep(context + all);
        ADD_FAILURE() << context << all << "\n  input kept in " << (fs::temp_directory_path() / "raylab_fuzz_failures").string();
    }
}

fs::path sourceRoot() { return rl::sourceRoot(); }

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace rl::fuzz
