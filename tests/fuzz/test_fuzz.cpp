// Issue 11: a seeded, time-bounded fuzzer that runs the real `raylab` binary
// on mutated scene files, command lines and shader folders (and, issue 35,
// configures mutated course files), in a temporary
// folder, and checks raylab's promise on every input:
//   - no signal (no crash) and no hang (a per-run timeout);
//   - a bad input gives a non-zero exit status and exactly one line on
//     stderr starting with "raylab: error:", naming the file (or option) at fault;
//   - a run that succeeds writes only finite numbers into its PFM;
//   - no file changes that the command did not name as an output, and a failed
//     run changes none at all (the previous outputs are kept).
//
// Seeds: RAYLAB_FUZZ_SEED=N picks another set of inputs (the suite's default is
// fixed, so CI is reproducible); RAYLAB_FUZZ_COUNT=N runs N inputs per test
// instead of the default; RAYLAB_FUZZ_SECONDS=S bounds each test's time (each
// test stops, passing, when S is used up, and says how many inputs it ran).
// A failure prints the seed of the input and keeps it in
// $TMPDIR/raylab_fuzz_failures/ so it can be run again by hand.
#include "fuzz/fuzz_support.h"
#include "support/test_support.h"

#include "core/message.h"
#include "course/exercise_registry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <sstream>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fs = std::filesystem;
using namespace rl::fuzz;

namespace {

std::vector<fs::path> bundledScenes() {
    std::vector<fs::path> out;
    for (const char* folder : {"scenes", "scenes/hard"})
        for (const auto& e : fs::directory_iterator(sourceRoot() / folder))
            if (e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// ---- Scene files -------------------------------------------------------------

// Every numeric literal's [begin, end) in a JSON text, outside strings.
std::vector<std::pair<std::size_t, std::size_t>> numberSpans(const std::string& text) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t j = i;
            while (j < text.size() && std::string("+-0123456789.eE").find(text[j]) != std::string::npos) ++j;
            out.push_back({i, j});
            i = j - 1;
        }
    }
    return out;
}

// Every value's start after a ':' (outside strings): where wrong types go.
std::vector<std::size_t> valueStarts(const std::string& text) {
    std::vector<std::size_t> out;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (inString) {
            if (text[i] == '\\') ++i;
            else if (text[i] == '"') inString = false;
        } else if (text[i] == '"') {
            inString = true;
        } else if (text[i] == ':') {
            std::size_t j = text.find_first_not_of(" \t\n", i + 1);
            if (j != std::string::npos) out.push_back(j);
        }
    }
    return out;
}

// The end of the JSON value starting at `start` (a scalar, or a balanced [...] / {...}).
std::size_t valueEnd(const std::string& text, std::size_t start) {
    if (text[start] == '[' || text[start] == '{') {
        int depth = 0;
        bool inString = false;
        for (std::size_t i = start; i < text.size(); ++i) {
            if (inString) {
                if (text[i] == '\\') ++i;
                else if (text[i] == '"') inString = false;
            } else if (text[i] == '"') {
                inString = true;
            } else if (text[i] == '[' || text[i] == '{') {
                ++depth;
            } else if ((text[i] == ']' || text[i] == '}') && --depth == 0) {
                return i + 1;
            }
        }
        return text.size();
    }
    if (text[start] == '"') {
        std::size_t i = start + 1;
        while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
        return std::min(i + 1, text.size());
    }
    std::size_t end = text.find_first_of(",}]\n", start);
    return end == std::string::npos ? text.size() : end;
}

const char* kHugeNumbers[] = {"1e400", "-1e400", "1e308", "-1.7976931348623157e308", "1e39", "3.5e38", "1e-400",
                              "4.9e-324", "1e9", "1000000001", "99999999999999999999999999", "-0", "0", "-1",
                              "1e300", "NaN", "Infinity", "-", "1.", ".5", "1e", "0x10", "1e-45"};
const char* kWrongTypes[] = {"\"text\"", "[]", "{}", "null", "true", "false", "[1,2]", "[1,2,3,4]", "[\"a\",1,2]",
                             "{\"x\":1}", "\"\"", "[[0,0,0]]", "\"\\u001b[31m\\n\""};

struct Mutation {
    std::string name;
    std::string text;
    bool certainlyBad = false;  // no scene can be read from it: exit 0 breaks the promise
};

Mutation mutateScene(const std::string& original, Rng& rng) {
    std::string t = original;
    auto at = [&](std::size_t n) { return n == 0 ? std::size_t(0) : rng.below(n); };
    switch (rng.below(15)) {
        case 0: {  // flip bits in a few bytes
            int n = 1 + int(rng.below(4));
            for (int k = 0; k < n && !t.empty(); ++k) t[at(t.size())] ^= char(1u << rng.below(8));
            return {"byte flip", t};
        }
        case 1: {  // truncation: bad when it cuts before the closing brace
            std::size_t cut = at(t.size());
            return {"truncation", t.substr(0, cut), cut <= t.rfind('}')};
        }
        case 2: {  // deep nesting spliced in as a value
            auto starts = valueStarts(t);
            if (starts.empty()) break;
            std::size_t s = starts[at(starts.size())];
            std::size_t depth = rng.pick<std::size_t>({65, 100, 1000, 100000});
            std::string deep = std::string(depth, '[') + std::string(rng.below(2) ? depth : 0, ']');
            t = t.substr(0, s) + deep + t.substr(valueEnd(t, s));
            return {"deep nesting " + std::to_string(depth), t, true};
        }
        case 3:
        case 4: {  // a huge, tiny or malformed number
            auto spans = numberSpans(t);
            if (spans.empty()) break;
            auto [b, e] = spans[at(spans.size())];
            std::string number = kHugeNumbers[rng.below(std::size(kHugeNumbers))];
            t = t.substr(0, b) + number + t.substr(e);
            return {"number " + number, t, number == "1e400" || number == "-1e400"};
        }
        case 5: {  // NUL followed by garbage
            std::size_t pos = rng.below(2) ? t.size() : at(t.size());
            std::string garbage(1, '\0');
            for (int k = 0, n = int(rng.below(40)); k < n; ++k) garbage += char(rng.below(256));
            t.insert(pos, garbage);
            return {"NUL and garbage", t, true};
        }
        case 6: {  // control characters, raw or escaped, in a string or anywhere
            const char* controls[] = {"\x1b[2J", "\n", "\r", "\x07", "\x7f", "\\u001b[31m", "\\n", "\xc2\x9b"};
            std::string c = controls[rng.below(std::size(controls))];
            std::size_t quote = t.find('"', at(t.size()));
            std::size_t pos = quote == std::string::npos ? at(t.size()) : quote + 1;
            t.insert(pos, c);
            return {"control characters", t};
        }
        case 7:
        case 8: {  // a value of the wrong type
            auto starts = valueStarts(t);
            if (starts.empty()) break;
            std::size_t s = starts[at(starts.size())];
            std::string v = kWrongTypes[rng.below(std::size(kWrongTypes))];
            t = t.substr(0, s) + v + t.substr(valueEnd(t, s));
            return {"wrong type " + v, t};
        }
        case 9: {  // a long string value or key
            std::size_t n = rng.pick<std::size_t>({300, 70000, 1 << 20});
            std::string s(n, char('a' + rng.below(26)));
            std::size_t pos = t.find('{');
            if (pos == std::string::npos) break;
            t.insert(pos + 1, (rng.below(2) ? "\"" + s + "\": 1," : "\"tonemap\": \"" + s + "\","));
            return {"long string " + std::to_string(n), t};
        }
        case 10: {  // many entries
            std::string many = ", \"spheres\": [";
            for (int k = 0, n = int(rng.pick<std::size_t>({65, 1000, 100000})); k < n; ++k) many += k ? ",{}" : "{}";
            std::size_t pos = t.rfind('}');  // last: of duplicate keys nlohmann keeps the last
            if (pos == std::string::npos) break;
            t.insert(pos, many + "]");
            return {"many spheres", t, true};
        }
        case 11: {  // delete or duplicate a random range
            std::size_t a = at(t.size()), n = std::min<std::size_t>(t.size() - a, 1 + rng.below(40));
            if (rng.below(2)) t.erase(a, n);
            else t.insert(a, t.substr(a, n));
            return {"splice", t};
        }
        case 13: {  // a valid scene far from the origin or huge (issue #23: NaN from 1e10 and 2^64)
            // The first "center", "position" or "target" set to (X, -X, -X),
            // or the first radius to X, X from 1e10 to 1e24 (a radius of 1e18
            // to 2^64 holds the camera inside): the picture must be finite or
            // the scene refused with one line.
            const char* far[] = {"1e10", "1e15", "3e17", "1e18", "1e19", "18446744073709551616", "1e24"};
            std::string big = far[rng.below(std::size(far))];
            bool radius = rng.below(2) == 0;
            std::string key = radius ? "\"radius\"" : rng.pick<std::string>({"\"center\"", "\"position\"", "\"target\""});
            std::size_t at0 = t.find(key);
            if (at0 == std::string::npos) break;
            std::size_t open = t.find_first_of(radius ? ":" : "[", at0 + key.size());
            if (open == std::string::npos) break;
            std::size_t close = t.find_first_of(radius ? ",}" : "]", open);
            if (close == std::string::npos) break;
            std::string value = radius ? ": " + big : "[" + big + ", -" + big + ", -" + big;
            t = t.substr(0, open) + value + t.substr(close);
            return {"far or huge " + key + " " + big, t};
        }
        case 12:  // random bytes
            for (std::size_t k = 0, n = rng.below(200); k < n; ++k) t.insert(at(t.size()), 1, char(rng.below(256)));
            return {"random bytes", t};
        default:  // a BOM, or a valid scene (the control case: it must render)
            if (rng.below(2)) return {"BOM", "\xef\xbb\xbf" + t};
            return {"unchanged", t};
    }
    return {"unchanged", t};
}

class Fuzz : public ::testing::Test {
protected:
    void SetUp() override { settings_ = Settings::fromEnvironment(); }
    Settings settings_;
};

TEST_F(Fuzz, SceneFiles) {
    std::vector<fs::path> scenes = bundledScenes();
    ASSERT_FALSE(scenes.empty());
    Budget budget(settings_, 300);
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "scene", i);
        const fs::path& source = scenes[rng.below(scenes.size())];
        Mutation m = mutateScene(readFile(source), rng);
        Sandbox box;
        box.write("scene.json", m.text);
        box.write("out.png", "the previous picture");  // a failed run must keep it
        Invocation run;
        run.args = {"render", "scene.json", "-o", "out.png", "--hdr", "out.pfm", "--size", "16x12"};
        if (rng.below(8) == 0) run.args.push_back("--cpu");
        run.outputs = {"out.png", "out.pfm"};
        run.culprits = {"scene.json"};
        run.description = source.filename().string() + ": " + m.name;
        run.seed = rng.seed();
        run.mayPass = !m.certainlyBad;
        expectPromise(box, run, settings_);
    }
    budget.report("scene files");
}

TEST_F(Fuzz, FilesThatAreNotFiles) {
    // FIFO, folder, device, link to a folder, empty, unreadable: in place of the scene or an output.
    Budget budget(settings_, 40);
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "special", i);
        Sandbox box;
        box.write("scene.json", readFile(sourceRoot() / "scenes/lecture.json"));
        const char* kinds[] = {"fifo", "dir", "device", "link-to-dir", "empty", "link-loop", "unreadable", "dangling"};
        std::string kind = kinds[rng.below(std::size(kinds))];
        const char* roles[] = {"scene", "png", "pfm", "csv"};
        std::string role = roles[rng.below(std::size(roles))];
        std::string name = role == "scene" ? "special.json" : "special." + role;
        if (!box.makeSpecial(name, kind)) continue;  // e.g. mknod without root
        Invocation run;
        if (role == "csv") {
            run.args = {"bench", "scene.json", "--size", "8x8", "--sweeps", "modes", "--frames", "1", "--warmup", "0",
                        "--reference-spp", "1", "--csv", name};
        } else {
            run.args = {"render", role == "scene" ? name : "scene.json", "-o", role == "png" ? name : "out.png",
                        "--size", "8x8"};
            if (role == "pfm") run.args.insert(run.args.end(), {"--hdr", name});
        }
        run.outputs = {"out.png"};
        run.culprits = {name};
        run.description = kind + " as the " + role;
        run.seed = rng.seed();
        // An empty regular file is an error for a scene; an unreadable one too unless we are root.
        run.mayPass = kind == "dangling" || (kind == "empty" && role != "scene") || (kind == "unreadable" && role != "scene") ||
                      (kind == "unreadable" && geteuid() == 0);
        if (run.mayPass) run.outputs.push_back(name);
        expectPromise(box, run, settings_);
    }
    budget.report("special files");
}

// ---- Command lines -------------------------------------------------------------

struct OptionSpec {
    const char* name;
    const char* kind;  // "int", "spp", "seconds", "size", "path", "out", "word", "flag"
};

const std::vector<std::pair<std::string, std::vector<OptionSpec>>>& commandSpecs() {
    static const std::vector<std::pair<std::string, std::vector<OptionSpec>>> specs = {
        {"render",
         {{"--output", "out"}, {"--hdr", "out"}, {"--size", "size"}, {"--spp", "spp"}, {"--backend", "word"},
          {"--impl", "path"}, {"--view", "word"}, {"--cpu", "flag"}, {"--generic", "flag"}}},
        {"check",
         {{"--impl", "path"}, {"--exercise", "word"}, {"--file", "path"}, {"--json", "out"}, {"--output", "outdir"},
          {"--timeout", "seconds"}, {"--backend", "word"}}},
        {"grade",
         {{"--output", "path"}, {"--jobs", "int"}, {"--timeout", "seconds"}, {"--rubric", "path"}, {"--shard", "word"},
          {"--backend", "word"}}},
        {"bench",
         {{"--csv", "out"}, {"--plot", "out"}, {"--size", "size"}, {"--warmup", "int"}, {"--frames", "int"},
          {"--reference-spp", "spp"}, {"--sweeps", "word"}, {"--backend", "word"}, {"--clock", "word"},
          {"--impl", "path"}}},
    };
    return specs;
}

// A value that is certainly wrong for an option of this kind.
std::string badValue(const std::string& kind, Rng& rng) {
    static const std::vector<std::string> numbers = {"", "-1", "0", "nan", "inf", "-inf", "1e999", "abc", "1x",
                                                     " 5", "99999999999999999999", "2.5", "0x10", "\x1b[31m", "--"};
    static const std::vector<std::string> sizes = {"", "0x0", "16384x16384", "-8x8", "8x", "x8", "8x8x8", "8by8",
                                                   "99999999999x2", "8 x 8", "\n8x8"};
    static const std::vector<std::string> paths = {"", "/nonexistent/x", "fifo", "dev", "folder/", "\x1b[2J",
                                                   std::string(5000, 'p'), "a\nb"};
    static const std::vector<std::string> words = {"", "bogus", "\x1b[31mred", std::string(3000, 'w'), "1/0", "0/0",
                                                   "3/2", "-1", "\t"};
    if (kind == "int") {
        std::string v = numbers[rng.below(numbers.size())];
        return v == "0" ? "-3" : v;  // --warmup 0 is fine
    }
    if (kind == "spp") return rng.pick<std::string>({"0", "2", "3", "1025", "4096", "-4", "", "nan", "1e3", "1.0e0x"});
    if (kind == "seconds") return rng.pick<std::string>({"-1", "0", "", "nan", "inf", "1e999", "86401", "abc", "-0"});
    if (kind == "size") return sizes[rng.below(sizes.size())];
    if (kind == "path") return paths[rng.below(paths.size())];
    if (kind == "outdir") return rng.pick<std::string>({"", "fifo", "dev", "scene.json", "/nonexistent/x/y"});
    // Any other name is a fine output file, even with control characters in it.
    if (kind == "out") return rng.pick<std::string>({"", "/nonexistent/x", "fifo", "dev", "folder", "folder/", "."});
    return words[rng.below(words.size())];
}

TEST_F(Fuzz, CommandLines) {
    Budget budget(settings_, 200);
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "cli", i);
        const auto& [command, options] = commandSpecs()[rng.below(commandSpecs().size())];
        Sandbox box;
        box.write("scene.json", readFile(sourceRoot() / "scenes/lecture.json"));
        box.write("out.png", "the previous picture");
        box.makeSpecial("fifo", "fifo");
        box.makeSpecial("folder", "dir");
        box.makeSpecial("dev", "device");
        Invocation run;
        run.args = {command};
        // A valid, fast base that the one bad value below breaks.
        if (command == "render") run.args.insert(run.args.end(), {"scene.json", "--size", "8x8", "-o", "out.png"});
        if (command == "check")
            run.args.insert(run.args.end(), {"-e", "1", "--timeout", "30", "--impl", (sourceRoot() / "solutions").string()});
        if (command == "grade") run.args.insert(run.args.end(), {"folder", "-o", "graded"});  // no students: fast
        if (command == "bench")
            run.args.insert(run.args.end(), {"scene.json", "--size", "8x8", "--frames", "1", "--warmup", "0",
                                             "--reference-spp", "1", "--sweeps", "modes"});
        std::vector<std::string> culprits;
        switch (rng.below(5)) {
            case 0: {  // an unknown flag
                std::string flag = rng.pick<std::string>({"--frobnicate", "-Z", "--spp=", "---", "--\x1b[31m"});
                run.args.push_back(flag);
                culprits = {rl::printable(flag.substr(0, flag.find('=')), 20)};
                run.description = "unknown flag " + flag;
                break;
            }
            case 1: {  // an option without its value, at the end
                const OptionSpec& o = options[rng.below(options.size())];
                if (std::string(o.kind) == "flag") continue;
                run.args.push_back(o.name);
                culprits = {o.name};
                run.description = std::string(o.name) + " without a value";
                break;
            }
            case 2: {  // an unknown command
                run.args = {rng.pick<std::string>({"bogus", "rendr", "\x1b[31m", "", "Render", "-x"})};
                culprits = {rl::printable(run.args[0], 20), "name a command"};
                run.description = "unknown command";
                break;
            }
            default: {  // one option with a bad value, the rest valid
                const OptionSpec& o = options[rng.below(options.size())];
                std::string kind = o.kind;
                if (kind == "flag") continue;
                std::string value = badValue(kind, rng);
                if (kind == "path" && value == "folder/" && command == "grade") value = "fifo";
                if (kind == "out" && value == "") value = "folder";
                run.args.insert(run.args.begin() + 1, {o.name, value});
                culprits = {o.name};  // the option, or the file it names
                if (!value.empty()) culprits.push_back(rl::printable(value, 20));
                run.description = std::string(o.name) + " " + value.substr(0, 40);
                break;
            }
        }
        run.outputs = {};
        run.culprits = culprits;
        run.seed = rng.seed();
        run.mayPass = false;
        expectPromise(box, run, settings_);
    }
    budget.report("command lines");
}

// ---- Shader folders ------------------------------------------------------------

// Shader sources are the other half of issue 11 (include expander, BOM,
// #line, declarations check), on another branch. Until it is merged:
//  - these cases must not crash, hang or print without bound, and exit
//    non-zero when the file is certainly broken; the message is not checked;
const std::vector<std::string>& namedAfterDiagnosticsMerge() {
    static const std::vector<std::string> cases = {"deleted function", "unclosed brace", "unclosed comment",
                                                   "garbage line", "truncation", "line directive", "empty file",
                                                   "huge include", "BOM", "long blank line"};
    return cases;
}
//  - these still crash the include expander's std::regex (SIGSEGV) and are
//    not run at all.
// After the merge, set kDiagnosticsMerged to true (or run with
// RAYLAB_FUZZ_AFTER_DIAGNOSTICS=1): every case runs, and each error must be one
// line naming the student's file.
const std::vector<std::string>& crashBeforeDiagnosticsMerge() {
    static const std::vector<std::string> cases = {"huge include", "long blank line"};
    return cases;
}
constexpr bool kDiagnosticsMerged = true;

TEST_F(Fuzz, ShaderFolders) {
    Budget budget(settings_, 60);
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(sourceRoot() / "solutions"))
        if (e.path().extension() == ".glsl") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "shader", i);
        Sandbox box;
        for (const fs::path& f : files) box.write("impl/" + f.filename().string(), readFile(f));
        const fs::path& victim = files[rng.below(files.size())];
        std::string name = "impl/" + victim.filename().string();
        std::string t = readFile(victim);
        std::string what;
        bool certainlyBad = true;
        switch (rng.below(12)) {
            case 0: {  // delete a function: from its signature to its closing brace
                std::size_t open = t.find("{\n");
                std::size_t close = t.find("\n}", open);
                std::size_t start = t.rfind('\n', open);
                if (open == std::string::npos || close == std::string::npos) continue;
                t.erase(start == std::string::npos ? 0 : start, close + 2 - (start == std::string::npos ? 0 : start));
                what = "deleted function";
                break;
            }
            case 1: t += "\nfloat unclosed() {\n"; what = "unclosed brace"; break;
            case 2: t += "\n/* an unclosed comment\n"; what = "unclosed comment"; break;
            case 3: t = "#include \"" + std::string(200000, 'i') + "\"\n" + t; what = "huge include"; break;
            case 4: t += "\nthis is not glsl;\n"; what = "garbage line"; break;
            case 5: {
                std::size_t brace = t.rfind('}');
                t = t.substr(0, brace == std::string::npos ? t.size() / 2 : brace);
                what = "truncation";
                break;
            }
            case 6: t = "#line 1000\n" + t + "\nsyntax error here\n"; what = "line directive"; break;
            case 7: t = ""; what = "empty file"; break;
            // Issue 22: array sizes behind a constant, a macro or a struct (refused with the line, before compiling).
            case 8: t += "\nconst int RL_FUZZ_N = 50000000;\nfloat rl_fuzz_big[RL_FUZZ_N];\n"; what = "array behind a const"; break;
            case 9: t += "\n#define RL_FUZZ_N 7000 * 7000\nfloat rl_fuzz_big[RL_FUZZ_N];\n"; what = "array behind a macro"; break;
            case 10:
                t += "\nstruct RlFuzz { float a[4000]; float b[4000]; };\nRlFuzz rl_fuzz_s;\n";
                what = "arrays in a struct";
                break;
            default:
                // Valid GLSL after the other half of the issue: a BOM, a line of 30,000 spaces.
                t = rng.below(2) ? "\xef\xbb\xbf" + t : std::string(30000, rng.below(2) ? ' ' : '\t') + "\n" + t;
                what = t[0] == '\xef' ? "BOM" : "long blank line";
                certainlyBad = false;
                break;
        }
        const bool merged = kDiagnosticsMerged || settings_.afterDiagnostics;
        const auto& crashing = crashBeforeDiagnosticsMerge();
        if (!merged && std::find(crashing.begin(), crashing.end(), what) != crashing.end()) continue;
        box.write(name, t);
        box.write("out.png", "the previous picture");
        Invocation run;
        run.args = {"render", "--size", "8x8", "--impl", "impl", "-o", "out.png"};
        // A unit whose functions only a scene with its define calls (unit.json
        // "shows_with": exercise 11 and RL_ENVIRONMENT, 12 and RL_ENV_OCCLUSION)
        // is rendered in such a scene (sky-spheres: an environment and several
        // spheres): the default scene never calls them, so a deleted function
        // there is no error (docs/decisions.md, "Optional exercises").
        const std::string unitId = victim.stem().string();
        for (const rl::ExerciseInfo& e : rl::allExercises())
            if (e.id == unitId && !e.showsWith.empty()) {
                ASSERT_TRUE(e.showsWith == "RL_ENVIRONMENT" || e.showsWith == "RL_ENV_OCCLUSION")
                    << e.id << ": which scene shows " << e.showsWith << "?";
                run.args.insert(run.args.begin() + 1,
                                (sourceRoot() / "scenes" / "environments" / "sky-spheres.json").string());
            }
        run.outputs = {"out.png"};
        run.culprits = {victim.filename().string()};
        run.description = victim.filename().string() + ": " + what;
        run.seed = rng.seed();
        run.mayPass = !certainlyBad;
        const auto& strict = namedAfterDiagnosticsMerge();
        run.lenientMessage = !merged && std::find(strict.begin(), strict.end(), what) != strict.end();
        run.compilerDiagnostics = true;
        expectPromise(box, run, settings_);
    }
    budget.report("shader folders");
}


// Issue 22: entries of SUBMISSIONS named with any bytes (0xFF, escapes, Canvas
// and Moodle shapes, Unicode): the run never stops, every entry is a student
// or an ignored entry with its reason, and summary.json is valid JSON.
// Issue 36: names of up to 248 bytes that escape to three times as many, the
// grader's own output names (grades-moodle.csv, students.txt, ...), bidi
// controls (U+202E) and raw ESC and BEL bytes, Moodle folders starting with
// '.': every student gets a folder of a bounded name, and no raw control or
// bidi character reaches index.html or summary.json.
TEST_F(Fuzz, SubmissionNames) {
    Budget budget(settings_, 12);
    const std::string stub = readFile(sourceRoot() / "exercises" / "01-camera.glsl");
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "names", i);
        Sandbox box;
        box.write("r.json", "{\"exercises\": [{\"id\": \"01-camera\", \"weight\": 10}]}");
        box.write("folder/.keep", "");
        std::set<std::string> names;
        const std::size_t entries = 1 + rng.below(4);
        for (std::size_t k = 0; k < entries; ++k) {
            std::string name;
            static const char* const kOutputs[] = {"grades.csv",       "grades-moodle.csv", "grades-canvas.csv",
                                                   "summary.json",     "students.txt",      "index.html",
                                                   "_reference",       "rubric.json",       "x.merging",
                                                   "grades-moodle.report.txt"};
            switch (rng.below(5)) {
                case 0:  // long: 0xE9 escapes to "%E9", three bytes each
                    name = std::string(60 + rng.below(160), rng.below(2) ? '\xe9' : 'a');  // + a suffix: within 255
                    break;
                case 1: name = kOutputs[rng.below(10)]; break;
                case 2: {  // bidi and terminal controls amid text
                    static const char* const kControls[] = {"\xe2\x80\xae", "\x1b[31m", "\x07", "\xe2\x81\xa6", "\r"};
                    name = "ab" + std::string(kControls[rng.below(5)]) + "gnp.exe" + std::to_string(k);
                    break;
                }
                default:
                    for (std::size_t n = 1 + rng.below(12); name.size() < n;) {
                        const char c = char(1 + rng.below(255));
                        if (c != '/') name += c;
                    }
            }
            const bool moodle = rng.below(4) == 1;
            if (name == "." || name == ".." || (name[0] == '.' && !moodle)) name = "x" + name;
            switch (moodle ? 1 : rng.below(4) == 1 ? 3 : rng.below(4)) {
                case 0: name += "_" + std::to_string(1000 + k) + "_7002" + std::to_string(k) + "_01-camera.glsl"; break;
                case 1:  // Moodle's folder, its full name first (may start with '.': graded, not hidden)
                    name = (rng.below(3) == 0 ? "." : "") + name + "_" + std::to_string(4000 + k) + "_assignsubmission_file_";
                    break;
                case 2: name += ".zip"; break;
                default: break;
            }
            if (!names.insert(name).second) continue;
            if (name.size() > 4 && name.compare(name.size() - 5, 5, ".glsl") == 0)
                box.write("folder/" + name, stub);
            else
                box.write("folder/" + name + (name.size() > 4 && name.compare(name.size() - 4, 4, ".zip") == 0 ? "" : "/01-camera.glsl"),
                          stub);  // a "zip" that is not one: refused, with the reason
        }
        Invocation run;
        run.args = {"grade", "folder", "-o", "graded", "--rubric", "r.json", "--timeout", "20"};
        run.description = "submission names";
        run.outputFolder = "graded";
        run.seed = rng.seed();
        run.mayPass = true;
        expectPromise(box, run, settings_);
        const fs::path summary = box.dir() / "graded" / "summary.json";
        ASSERT_TRUE(fs::exists(summary)) << "seed " << run.seed << ": no summary.json";
        nlohmann::json j;
        try {
            j = nlohmann::json::parse(readFile(summary));
        } catch (const std::exception& e) {
            ADD_FAILURE() << "seed " << run.seed << ": summary.json is not JSON: " << e.what();
        }
        // Every entry is a student (Canvas parts of one student count once) or ignored with its reason
        // ("folder/.keep" is hidden: one more ignored).
        const std::size_t listed = j.value("students", std::size_t(0)) + j.value("ignored_count", std::size_t(0));
        EXPECT_GE(listed, 2u) << "seed " << run.seed;
        EXPECT_LE(listed, names.size() + 1) << "seed " << run.seed;
        EXPECT_TRUE(j.value("students_not_written", nlohmann::json::array()).empty()) << "seed " << run.seed << ": " << j.dump();
        // Every student has its folder, under a bounded name; the ids list is the students' count.
        std::size_t ids = 0;
        std::istringstream list(readFile(box.dir() / "graded" / "students.txt"));
        for (std::string id; std::getline(list, id); ++ids) {
            EXPECT_LE(id.size(), 120u) << "seed " << run.seed;
            EXPECT_TRUE(fs::is_regular_file(box.dir() / "graded" / id / "grade.json")) << "seed " << run.seed << ": " << id;
        }
        EXPECT_EQ(ids, j.value("students", std::size_t(0))) << "seed " << run.seed;
        // What a browser or a terminal shows: no raw control character (but newline and tab), no bidi control.
        for (const char* file : {"index.html", "summary.json", "grades.csv"}) {
            const std::string text = readFile(box.dir() / "graded" / file);
            for (char c : text)
                if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') || c == 0x7f) {
                    ADD_FAILURE() << "seed " << run.seed << ": " << file << " holds the raw byte " << int(c);
                    break;
                }
            EXPECT_EQ(text.find("\xe2\x80\xae"), std::string::npos) << "seed " << run.seed << ": U+202E in " << file;
            EXPECT_EQ(text.find("\xe2\x81\xa6"), std::string::npos) << "seed " << run.seed << ": U+2066 in " << file;
        }
        if (HasFailure()) box.keep("submission names, seed " + std::to_string(run.seed));
    }
    budget.report("submission names");
}

}  // namespace

// ---- Course files (issue 35) ---------------------------------------------------
//
// A unit's unit.json mutated as the scene files are, a unit folder renamed
// to an odd name, or the manifest mutated, in a copy of course/'s
// configure-time files; then configured (cmake -P cmake/course.cmake, what
// every build runs first). The promise: it configures, or it stops with one
// message line naming a file of course/ (CMake's own "CMake Error at" header
// aside), never a Python traceback or an internal error.
TEST_F(Fuzz, CourseFiles) {
    const fs::path course = sourceRoot() / "course";
    std::vector<std::string> units;
    for (const auto& e : fs::directory_iterator(course))
        if (e.is_directory()) units.push_back(e.path().filename().string());
    std::sort(units.begin(), units.end());
    ASSERT_FALSE(units.empty());
    Budget budget(settings_, 24);
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "course", i);
        const fs::path root = rl::test::freshTempDir("fuzz-course");
        fs::create_directories(root / "course");
        for (const char* file : {"manifest.txt", "unit.schema.json"})
            fs::copy_file(course / file, root / "course" / file);
        for (const std::string& unit : units) {
            fs::create_directories(root / "course" / unit);
            for (const char* file : {"unit.json", "stub.glsl", "solution.glsl"})
                if (fs::exists(course / unit / file)) fs::copy_file(course / unit / file, root / "course" / unit / file);
        }
        const std::string unit = units[rng.below(units.size())];
        std::string description;
        switch (rng.below(3)) {
            case 0: {
                Mutation m = mutateScene(readFile(course / unit / "unit.json"), rng);
                rl::test::writeText(root / "course" / unit / "unit.json", m.text);
                description = unit + "/unit.json: " + m.name;
                break;
            }
            case 1: {
                const std::string odd = rng.pick<std::string>(
                    {"12 my unit", "12-q\"x", "12-a;b", "helpers", "12-\xc3\xa9t\xc3\xa9", "12-", "123-x", "12-A",
                     "12-$(id)", "12-a\\b", "12-a'b"});
                fs::create_directories(root / "course" / odd);
                for (const char* file : {"unit.json", "stub.glsl"})
                    fs::copy_file(course / unit / file, root / "course" / odd / file);
                description = "a unit folder named " + odd;
                break;
            }
            default: {
                Mutation m = mutateScene(readFile(course / "manifest.txt"), rng);
                rl::test::writeText(root / "course" / "manifest.txt", m.text);
                description = "manifest.txt: " + m.name;
                break;
            }
        }
        const rl::test::CommandResult r = rl::test::runShell(
            "cmake -DRAYLAB_ROOT_DIR=" + rl::test::shellQuoted(root.string()) + " -DRAYLAB_GENERATED_DIR=" +
            rl::test::shellQuoted((root / "generated").string()) + " -P " +
            rl::test::shellQuoted((sourceRoot() / "cmake" / "course.cmake").string()) + " 2>&1");
        if (r.status == 0) continue;
        // CMake's message: "CMake Error at FILE:LINE (message):", then the text indented.
        std::vector<std::string> text;
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);)
            if (line.rfind("  ", 0) == 0) text.push_back(line);
        EXPECT_EQ(text.size(), 1u) << "seed " << rng.seed() << ", " << description << ":\n" << r.output;
        EXPECT_EQ(r.output.find("Traceback"), std::string::npos) << description << ":\n" << r.output;
        EXPECT_EQ(r.output.find("internal error"), std::string::npos) << description << ":\n" << r.output;
        EXPECT_NE(r.output.find("course/"), std::string::npos) << description << ":\n" << r.output;
    }
    budget.report("course files");
}

// ---- Image headers (issue 34) ----------------------------------------------------

// An environment scene whose image's header is mutated where the sizes are
// read: the .hdr's resolution line and the PFM's size line, with zero,
// negative, wrapped (2^32 + n), huge, missing and trailing numbers. Every one
// is refused in one line naming the image, or decodes; none crashes (stb's
// decoder divided by a width of 0 and took 4294967300 for 4).
TEST_F(Fuzz, ImageHeaders) {
    const fs::path folder = sourceRoot() / "scenes" / "environments";
    const std::string hdr = readFile(folder / "sky.hdr");
    const std::string sceneText = readFile(folder / "sky-spheres.json");
    Budget budget(settings_, 40);
    for (std::uint64_t i = 0; budget.next(); ++i) {
        Rng rng(settings_.seed, "image", i);
        // Sizes no image can have, and a few it can (which then decode or
        // not, as the pixel data after them allows).
        const std::set<std::string> possible = {"1", "4", "7", "8", "128", "256"};
        auto odd = [&]() -> std::string {
            return rng.pick<std::string>({"0", "-1", "-128", "4294967296", "4294967300", "2147483648", "99999999999",
                                          "", " ", "1e3", "0x10", "+8", "00", "1", "7", "4097", "256 junk"});
        };
        const bool pfm = rng.below(2) == 0;
        std::string image, name, description, w, h;
        if (pfm) {
            w = rng.below(3) ? odd() : "8";
            h = rng.below(3) ? odd() : "4";
            image = std::string(rng.below(2) ? "PF" : "Pf") + "\n" + w + " " + h + "\n-1.0\n" +
                    std::string(8 * 4 * 12, '\0');
            name = "env.pfm";
            description = "PFM size line '" + w + " " + h + "'";
        } else {
            const std::size_t line = hdr.find("\n\n") + 2, end = hdr.find('\n', line);
            h = rng.below(3) ? odd() : "128";
            w = rng.below(3) ? odd() : "256";
            const std::string resolution = rng.pick<std::string>({"-Y ", "+Y ", "-Y  ", "-X "}) + h +
                                           rng.pick<std::string>({" +X ", " -X ", " +X  ", "+X "}) + w;
            // The sky's pixels, or a few zero bytes (a small image's flat scanlines).
            image = hdr.substr(0, line) + resolution + (rng.below(2) ? hdr.substr(end) : "\n" + std::string(256, '\0'));
            name = "env.hdr";
            description = ".hdr resolution line '" + resolution + "'";
        }
        Sandbox box;
        box.write(name, image);
        std::string scene = sceneText;
        const std::size_t at = scene.find("\"sky.hdr\"");
        ASSERT_NE(at, std::string::npos) << "sky-spheres.json names sky.hdr";
        scene.replace(at, 9, "\"" + name + "\"");
        box.write("scene.json", scene);
        box.write("out.png", "the previous picture");
        Invocation run;
        run.args = {"render", "scene.json", "-o", "out.png", "--size", "16x12"};
        run.outputs = {"out.png"};
        run.culprits = {name};
        run.description = description;
        run.seed = rng.seed();
        run.mayPass = possible.count(w) && possible.count(h);  // a wrapped 4294967300 must not read as 4
        expectPromise(box, run, settings_);
    }
    budget.report("image headers");
}
