#include "grading/submission.h"

#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/file_handle.h"
#include "grading/atomic_file.h"
#include "grading/entry_name.h"
#include "core/legacy_text.h"
#include "grading/roster.h"
#include "grading/safe_unzip.h"
#include "shader/source_assembler.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

namespace fs = std::filesystem;

namespace rl {

namespace {

// Limits on what is copied from one submission: far above a real one.
// Entries looked at in full (any shader file, for #include); past this only
// files named as an exercise are kept, so a finished 05-ggx.glsl beside
// 10,000 generated files is still found. A real submission holds under 100.
constexpr std::size_t kMaxWalkedEntries = 5000;  // after build folders and .git are left out
// Entries listed at all: past this the submission is REFUSED, naming the
// limit (listing 200,000 names takes about 0.3 s; a submission this big is
// not a student's work but a disk image or a home folder).
constexpr std::size_t kMaxListedEntries = 200000;
constexpr int kMaxWalkDepth = 16;                  // "any depth": deeper than any real project
constexpr int kMaxZipDepth = 3;                    // a zip in a zip in a zip
constexpr int kMaxZips = 16;                       // each one within safe_unzip.h's limits
constexpr std::size_t kMaxCopiedFiles = 200;
constexpr std::uintmax_t kMaxCopiedBytes = 8u << 20;

bool endsWithZip(const std::string& name) {
    if (name.size() < 5) return false;
    std::string tail = name.substr(name.size() - 4);
    std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ".zip";
}

bool isHidden(const std::string& name) { return name.empty() || name[0] == '.' || name == "__MACOSX"; }

bool isShaderSource(const fs::path& p) {
    static const std::set<std::string> kinds = {".glsl", ".frag", ".vert", ".inc", ".h", ".glslinc"};
    return kinds.count(p.extension().string()) > 0;
}

std::string parentOf(const std::string& rel) {
    auto slash = rel.rfind('/');
    return slash == std::string::npos ? "" : rel.substr(0, slash);
}

std::string nameOf(const std::string& rel) {
    auto slash = rel.rfind('/');
    return slash == std::string::npos ? rel : rel.substr(slash + 1);
}

int depthOf(const std::string& rel) { return rel.empty() ? 0 : int(std::count(rel.begin(), rel.end(), '/')) + 1; }

std::string listSome(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t k = 0; k < names.size() && k < 5; ++k) out += (k ? ", " : "") + names[k];
    if (names.size() > 5) out += " and " + std::to_string(names.size() - 5) + " more";
    return out;
}

std::string kib(std::uintmax_t bytes) { return std::to_string((bytes + 1023) / 1024) + " KiB"; }

// Copies a regular file without following links or blocking on special files.
bool copyRegularFile(const fs::path& from, const fs::path& to, std::string& why) {
    InputFile in(from, InputFile::Links::Refuse);
    if (!in.ok()) {
        why = in.error().message();
        return false;
    }
    if (in.type() != fs::file_type::regular) {
        why = "not a regular file";
        return false;
    }
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    NewFile out(to);
    if (!out.ok()) {
        why = out.error().message();
        return false;
    }
    char buffer[65536];
    for (;;) {
        std::ptrdiff_t n = in.read(buffer, sizeof buffer);
        if (n < 0) {
            why = in.error().message();
            return false;
        }
        if (n == 0) return true;
        if (!out.write(buffer, std::size_t(n))) {
            why = out.error().message();
            return false;
        }
    }
}

// Folders never searched: build output, version control, editors' and
// macOS's droppings. A repository's zip holds them; the student's work does not.
bool isSkippedFolder(const std::string& name) {
    std::string l = name;
    std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return isHidden(name) || l == "build" || l.rfind("build-", 0) == 0 || l.rfind("build_", 0) == 0 ||
           l.rfind("cmake-build-", 0) == 0 || l == "cmakefiles" || l == "node_modules" || l == "_deps";
}

std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// The exercise a file name stands for: "05-ggx.glsl" exactly, or a renamed
// copy: any case ("05-ggx.GLSL"), a browser's " (1)", Canvas's "-1" for a
// resubmission, " copy", "_" or " " for "-", a ".txt" an editor added.
const ExerciseInfo* exerciseNamed(const std::string& name, bool& exact) {
    exact = false;
    for (const ExerciseInfo& e : allExercises())
        if (name == e.file()) {
            exact = true;
            return &e;
        }
    std::string stem = lowerCase(name);
    if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".txt") == 0) stem.resize(stem.size() - 4);
    if (stem.size() <= 5 || stem.compare(stem.size() - 5, 5, ".glsl") != 0) return nullptr;
    stem.resize(stem.size() - 5);
    for (char& c : stem)
        if (c == '_' || c == ' ') c = '-';
    auto strip = [&stem](const std::regex& tail) {
        std::smatch m;
        if (std::regex_search(stem, m, tail)) stem = m.prefix();
    };
    static const std::regex copyNumber(R"(-*\(\d+\)$)"), copyWord(R"(-copy(-\d+)?$)"), dashNumber(R"(-\d+$)");
    strip(copyNumber);
    strip(copyWord);
    for (const ExerciseInfo& e : allExercises())
        if (stem == e.id) return &e;
    strip(dashNumber);  // last: "05-ggx-1" is Canvas's second upload of 05-ggx.glsl
    for (const ExerciseInfo& e : allExercises())
        if (stem == e.id) return &e;
    return nullptr;
}

// The source with comments blanked out (newlines kept, so lines still count).
std::string withoutComments(const std::string& text) {
    std::string out = text;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            std::size_t end = out.find("*/", i + 2);
            end = end == std::string::npos ? out.size() : end + 2;
            for (; i < end; ++i)
                if (out[i] != '\n') out[i] = ' ';
            --i;
        }
    }
    return out;
}

int lineAt(const std::string& text, std::size_t offset) {
    return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(std::min(offset, text.size())), '\n'));
}

// A loop that can never end: `while (true)`, `while (1)` or a `for` without
// a condition, whose body holds no break, return or discard. On a GPU it
// hangs (the driver resets); llvmpipe alone stops it after 65535 iterations
// and renders something. Returns the line of the loop, or 0.
int endlessLoopLine(const std::string& source) {
    const std::string code = withoutComments(source);
    static const std::regex loop(R"(\bwhile\s*\(\s*(true|1)\s*\)|\bfor\s*\([^;()]*;\s*;)");
    static const std::regex exit(R"(\b(break|return|discard)\b)");
    for (auto it = std::sregex_iterator(code.begin(), code.end(), loop); it != std::sregex_iterator(); ++it) {
        std::size_t at = std::size_t(it->position()) + std::size_t(it->length());
        if ((*it)[0].str().rfind("for", 0) == 0) {  // past the for's closing parenthesis
            int depth = 1;
            for (; at < code.size() && depth > 0; ++at) depth += code[at] == '(' ? 1 : code[at] == ')' ? -1 : 0;
        }
        while (at < code.size() && std::isspace(static_cast<unsigned char>(code[at]))) ++at;
        if (at >= code.size()) break;
        std::size_t end = at;
        if (code[at] == '{') {
            int depth = 0;
            for (; end < code.size(); ++end) {
                depth += code[end] == '{' ? 1 : code[end] == '}' ? -1 : 0;
                if (depth == 0) break;
            }
        } else {
            end = code.find(';', at);
            if (end == std::string::npos) end = code.size();
        }
        // A `do { } while (true);` ends in the while: its body is before it, and not looked at.
        std::size_t before = std::size_t(it->position());
        while (before > 0 && std::isspace(static_cast<unsigned char>(code[before - 1]))) --before;
        if (before > 0 && code[before - 1] == '}') continue;
        std::string body = code.substr(at, end - at + 1);
        if (!std::regex_search(body, exit)) return lineAt(code, std::size_t(it->position()));
    }
    return 0;
}

// The number of tokens the preprocessor would make of the file's code, with
// every object-like macro expanded (a macro bomb doubles it per definition:
// #define A1 A0 A0, #define A2 A1 A1, ...). Stops counting at `limit`.
double macroExpansion(const std::string& source, std::string& biggest, int& line, double limit) {
    const std::string code = withoutComments(source);
    static const std::regex define(R"(^\s*#\s*define\s+([A-Za-z_]\w*)(\([^)]*\))?(.*)$)");
    static const std::regex identifier(R"([A-Za-z_]\w*)");
    std::map<std::string, std::pair<std::string, int>> macros;  // name -> body, line
    std::vector<std::string> codeLines;
    std::istringstream lines(code);
    int number = 0;
    for (std::string l; std::getline(lines, l);) {
        ++number;
        std::smatch m;
        if (std::regex_match(l, m, define))
            macros[m[1]] = {m[3], number};
        else if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] != '#')
            codeLines.push_back(l);
    }
    std::map<std::string, double> size;
    std::set<std::string> open;  // a macro is not expanded inside itself
    std::function<double(const std::string&)> sizeOf = [&](const std::string& name) -> double {
        auto known = size.find(name);
        if (known != size.end()) return known->second;
        auto macro = macros.find(name);
        if (macro == macros.end() || open.count(name)) return 1;
        open.insert(name);
        double n = 0;
        const std::string& body = macro->second.first;
        for (auto it = std::sregex_iterator(body.begin(), body.end(), identifier); it != std::sregex_iterator() && n < limit; ++it)
            n += sizeOf(it->str());
        open.erase(name);
        return size[name] = std::max(n, 1.0);
    };
    double total = 0;
    for (const std::string& l : codeLines)
        for (auto it = std::sregex_iterator(l.begin(), l.end(), identifier); it != std::sregex_iterator() && total < limit; ++it)
            total += sizeOf(it->str());
    double most = 0;
    for (const auto& [name, body] : macros)
        if (sizeOf(name) > most) {
            most = sizeOf(name);
            biggest = name;
            line = body.second;
        }
    return total;
}

bool wantedInZip(const std::string& path) {
    std::string rest = path;
    for (auto slash = rest.find('/'); slash != std::string::npos; slash = rest.find('/')) {
        if (isSkippedFolder(rest.substr(0, slash))) return false;
        rest = rest.substr(slash + 1);
    }
    bool exact;
    return isShaderSource(lowerCase(rest)) || endsWithZip(rest) || exerciseNamed(rest, exact) != nullptr;
}

// One thing found in the submission, as lstat sees it (links are never followed).
struct Item {
    enum class Type { File, Link, Other, Unextracted } type;
    std::string rel;         // shown path inside the submission ("repo.zip/exercises/05-ggx.glsl")
    fs::path source;         // where a File is read
    std::uintmax_t size = 0;
    std::string refusedWhy;  // a link or special entry of a zip
};

// Walks folders and extracts zips (nested ones too) into the scratch folder.
class Collector {
public:
    explicit Collector(fs::path scratch) : scratch_(std::move(scratch)) {}
    std::vector<Item> items;
    std::vector<std::string> folders;     // every folder seen ("exercises", "repo.zip/x")
    std::set<std::string> skippedFolders; // not searched ("build/", ".git/")
    std::vector<std::string> notes;
    std::string firstZipProblem;          // a zip that was refused, for when nothing else is found
    std::string overLimit;                // more than kMaxListedEntries: the submission is refused with this
    std::size_t unlooked = 0;             // files past kMaxWalkedEntries not named as exercises: ignored, counted

    void folder(const fs::path& dir, const std::string& prefix, int zipDepth) {
        std::error_code ec;
        fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
        if (ec) {
            notes.push_back((prefix.empty() ? std::string("the submission") : prefix) + " cannot be listed (" +
                            ec.message() + ")");
            return;
        }
        for (; it != end; it.increment(ec)) {
            if (ec) break;
            if (++walked_ > kMaxListedEntries) {
                overLimit = "the submission holds more than " + std::to_string(kMaxListedEntries) +
                            " files and folders (the limit): refused, submit your exercise files only";
                break;
            }
            const fs::path& p = it->path();
            const std::string name = p.filename().string();
            if (walked_ > kMaxWalkedEntries) {
                // Past the first 5,000: folders are still searched, only exercise files are kept.
                if (walked_ == kMaxWalkedEntries + 1)
                    notes.push_back("the submission holds more than " + std::to_string(kMaxWalkedEntries) +
                                    " files; among the rest only files named as exercises were looked for");
                bool exact = false;
                fs::file_status st = it->symlink_status(ec);
                if (fs::is_directory(st) && (isSkippedFolder(name) || it.depth() + 1 >= kMaxWalkDepth))
                    it.disable_recursion_pending();
                else if (!fs::is_directory(st) && !exerciseNamed(name, exact))
                    ++unlooked;
                else if (!fs::is_directory(st))
                    items.push_back({fs::is_symlink(st) ? Item::Type::Link : fs::is_regular_file(st) ? Item::Type::File
                                                                                                     : Item::Type::Other,
                                     prefix + p.lexically_relative(dir).generic_string(), p,
                                     fs::is_regular_file(st) ? it->file_size(ec) : 0, ""});
                continue;
            }
            std::string rel = prefix + p.lexically_relative(dir).generic_string();
            fs::file_status st = it->symlink_status(ec);
            if (fs::is_directory(st)) {
                if (isSkippedFolder(name)) {
                    if (!isHidden(name) || name == ".git") skippedFolders.insert(name + "/");
                    it.disable_recursion_pending();
                } else if (it.depth() + 1 >= kMaxWalkDepth) {
                    it.disable_recursion_pending();
                } else {
                    folders.push_back(rel);
                }
                continue;
            }
            if (fs::is_symlink(st)) {
                items.push_back({Item::Type::Link, rel, p, 0, ""});
            } else if (fs::is_regular_file(st)) {
                std::uintmax_t size = it->file_size(ec);
                if (endsWithZip(name) && zipDepth < kMaxZipDepth)
                    zip(p, rel + "/", zipDepth + 1);
                else
                    items.push_back({Item::Type::File, rel, p, size, ""});
            } else {
                items.push_back({Item::Type::Other, rel, p, 0, ""});
            }
        }
    }

    // Extracts the wanted entries of a zip and walks them; returns the reason when refused.
    std::string zip(const fs::path& zipPath, const std::string& prefix, int zipDepth) {
        if (++zips_ > kMaxZips) {
            std::string why = prefix.substr(0, prefix.size() - 1) + ": not opened, the submission holds more than " +
                              std::to_string(kMaxZips) + " zips";
            notes.push_back(why);
            return why;
        }
        fs::path dest = scratch_ / ("zip" + std::to_string(zips_));
        try {
            UnzipResult r = extractZipSafely(zipPath, dest, UnzipLimits{}, wantedInZip);
            for (const auto& [rel, why] : r.refused) items.push_back({Item::Type::Link, prefix + rel, {}, 0, why});
            for (const std::string& rel : r.skipped) {
                std::string shown = prefix + rel;
                bool skippedInside = false;
                std::string rest = rel;
                for (auto slash = rest.find('/'); slash != std::string::npos; slash = rest.find('/')) {
                    std::string part = rest.substr(0, slash);
                    if (isSkippedFolder(part)) {
                        if (!isHidden(part) || part == ".git") skippedFolders.insert(part + "/");
                        skippedInside = true;
                        break;
                    }
                    rest = rest.substr(slash + 1);
                }
                if (!skippedInside && !isHidden(nameOf(rel))) items.push_back({Item::Type::Unextracted, shown, {}, 0, ""});
            }
        } catch (const Error& e) {
            std::string why = e.what();
            if (!prefix.empty()) why = prefix.substr(0, prefix.size() - 1 - zipPath.filename().string().size()) + why;
            if (firstZipProblem.empty()) firstZipProblem = why;
            if (!prefix.empty()) notes.push_back("refused the zip " + why);  // the submission itself: its reason says it
            return why;
        }
        folder(dest, prefix, zipDepth);
        return "";
    }

private:
    fs::path scratch_;
    int zips_ = 0;
    std::size_t walked_ = 0;
};

bool hiddenPath(const std::string& rel) {
    for (std::string d = rel; !d.empty(); d = parentOf(d))
        if (isHidden(nameOf(d))) return true;
    return false;
}

// Chooses the exercise files among everything found and copies them (and the
// shader files beside them, for #include) into `staging`.
void stageItems(const std::vector<Item>& items, const Collector& found, const fs::path& staging,
                const std::string& shownName, StagedSubmission& out) {
    bool anyFile = std::any_of(items.begin(), items.end(), [](const Item& e) { return !isHidden(nameOf(e.rel)); });
    if (!anyFile) {
        out.problem = found.firstZipProblem.empty() ? StagedSubmission::Problem::Empty : StagedSubmission::Problem::Refused;
        out.problemReason = found.firstZipProblem.empty()
                                ? "the submission is empty: " + shownName + " holds no files to grade"
                                : "the submission was refused: " + found.firstZipProblem;
        return;
    }

    // Every candidate for every exercise, by folder.
    struct Candidate {
        const Item* item;
        bool exact;
        bool started;  // a readable file that is not the unchanged stub
    };
    std::map<std::string, std::map<std::string, std::vector<Candidate>>> byFolder;  // folder -> exercise file -> candidates
    for (const Item& e : items) {
        if (e.type == Item::Type::Unextracted || hiddenPath(e.rel)) continue;
        bool exact = false;
        const ExerciseInfo* info = exerciseNamed(nameOf(e.rel), exact);
        if (!info) continue;
        bool started = e.type == Item::Type::File && e.size <= kMaxShaderFileBytes && !isUnchangedStub(e.source, *info);
        byFolder[parentOf(e.rel)][info->file()].push_back({&e, exact, started});
    }
    if (byFolder.empty()) {
        if (!found.firstZipProblem.empty()) {
            out.problem = StagedSubmission::Problem::Refused;
            out.problemReason = "the submission was refused: " + found.firstZipProblem;
            return;
        }
        std::vector<std::string> names;
        for (const Item& e : items)
            if (!hiddenPath(e.rel)) names.push_back(e.rel);
        out.problem = StagedSubmission::Problem::Empty;
        out.problemReason = "no exercise files (" +
                            (requiredExercises().empty()
                                 ? std::string("none in the course")
                                 : requiredExercises().front().file() + " ... " + requiredExercises().back().file()) +
                            ") in the submission " + shownName +
                            "; it holds " + listSome(names);
        return;
    }
    // In one folder, the exact name wins over renamed copies; among copies the
    // last name in order ("05-ggx (2).glsl" after "05-ggx (1).glsl": the later download).
    auto best = [](const std::vector<Candidate>& c) {
        const Candidate* pick = &c[0];
        for (const Candidate& x : c)
            if ((x.exact && !pick->exact) || (x.exact == pick->exact && x.item->rel > pick->item->rel)) pick = &x;
        return *pick;
    };
    // The graded folder: the most exercises begun, then the most exercise
    // files, then the shallowest, then the first name. A stub left at the top
    // never beats a finished exercises/ folder.
    std::string root;
    std::tuple<int, int, int> rootScore{-1, -1, 0};
    for (const auto& [folder, exercises] : byFolder) {
        int begun = 0;
        for (const auto& [file, candidates] : exercises) begun += best(candidates).started;
        std::tuple<int, int, int> score{begun, int(exercises.size()), -depthOf(folder)};
        if (score > rootScore) {
            rootScore = score;
            root = folder;
        }
    }
    if (!root.empty()) out.notes.push_back("graded the folder " + root + "/ inside the submission");

    // The file graded for each exercise: from the graded folder, else the best elsewhere.
    std::map<std::string, Candidate> chosen;  // exercise file -> candidate
    for (const auto& [file, candidates] : byFolder[root]) chosen.emplace(file, best(candidates));
    std::set<std::string> otherFolders;
    for (const ExerciseInfo& info : allExercises()) {
        if (chosen.count(info.file())) continue;
        std::optional<Candidate> pick;
        for (const auto& [folder, exercises] : byFolder) {
            auto it = exercises.find(info.file());
            if (folder == root || it == exercises.end()) continue;
            Candidate c = best(it->second);
            if (!pick || (c.started && !pick->started) ||
                (c.started == pick->started && depthOf(folder) < depthOf(parentOf(pick->item->rel))))
                pick = c;
        }
        if (pick) {
            chosen.emplace(info.file(), *pick);
            out.notes.push_back(info.file() + ": graded " + pick->item->rel + " (not in the graded folder)");
        }
    }
    for (const auto& [folder, exercises] : byFolder)
        for (const auto& [file, candidates] : exercises)
            for (const Candidate& c : candidates)
                if (chosen.at(file).item != c.item) otherFolders.insert(c.item->rel);
    if (!otherFolders.empty())
        out.notes.push_back("other copies of exercise files were not graded: " +
                            listSome(std::vector<std::string>(otherFolders.begin(), otherFolders.end())));
    for (const std::string& folder : found.folders) {
        bool exact = false;
        if (parentOf(folder) == root && exerciseNamed(nameOf(folder), exact) && exact)
            out.notes.push_back(nameOf(folder) + " is a folder, not a file: not graded");
    }
    if (!found.skippedFolders.empty())
        out.notes.push_back("not searched: " +
                            listSome(std::vector<std::string>(found.skippedFolders.begin(), found.skippedFolders.end())) +
                            " (build output and version control)");

    std::size_t copied = 0;
    std::uintmax_t copiedBytes = 0;
    std::vector<std::string> refusedOther, ignored;
    auto fits = [&](std::uintmax_t size) {
        return copied < kMaxCopiedFiles && copiedBytes + size <= kMaxCopiedBytes;
    };
    // The exercise files first: they are what the student is graded on.
    for (const auto& [file, c] : chosen) {
        const Item& e = *c.item;
        if (!c.exact) out.notes.push_back("graded " + e.rel + " as " + file);
        if (e.type != Item::Type::File) {
            std::string why = !e.refusedWhy.empty()          ? e.refusedWhy
                              : e.type == Item::Type::Link ? "a symbolic link (links are never followed)"
                                                            : "not a regular file";
            out.refused[file] = e.rel + " is " + why + ": refused, grading reads only regular files inside your own submission";
            continue;
        }
        if (e.size > kMaxShaderFileBytes) {
            out.refused[file] = e.rel + ": file is " + kib(e.size) + ", over the " + kib(kMaxShaderFileBytes) +
                                " limit for a shader file";
            continue;
        }
        if (!fits(e.size)) {
            out.refused[file] = e.rel + ": not read, the submission holds too many shader files";
            continue;
        }
        std::string why;
        if (!copyRegularFile(e.source, staging / file, why)) {
            out.refused[file] = e.rel + ": cannot be read (" + why + ")";
            continue;
        }
        ++copied;
        copiedBytes += e.size;
        // A UTF-8 byte-order mark (Notepad's) is no GLSL: removed, and said so.
        std::string text = readWholeFile(staging / file);
        if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {
            writeFileAtomic(staging / file, text.substr(3));
            out.notes.push_back("removed the UTF-8 byte-order mark at the start of " + e.rel);
        }
        // Windows-1252 bytes in comments: read as such, with a note; outside comments: refused naming the byte.
        {
            LegacyTextResult legacy = commentsFromWindows1252(readWholeFile(staging / file));
            if (legacy.badLine > 0) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "0x%02X", legacy.badByte);
                out.refused[file] = e.rel + ":" + std::to_string(legacy.badLine) + ": file is not UTF-8 text: byte " +
                                    byte + " (at offset " + std::to_string(legacy.badOffset) +
                                    ") outside a comment; save the file as UTF-8";
                continue;
            }
            if (legacy.converted > 0) {
                writeFileAtomic(staging / file, legacy.text);
                out.notes.push_back(e.rel + ": " + std::to_string(legacy.converted) + " byte" +
                                    (legacy.converted == 1 ? "" : "s") + " in comments (first on line " +
                                    std::to_string(legacy.firstConvertedLine) +
                                    ") are not UTF-8 and were read as Windows-1252; save the file as UTF-8");
            }
        }
        // The checks the shader assembler makes on every file (size, UTF-8, NUL
        // bytes), here, so that the reason names the student's own file.
        try {
            readSourceFile(staging / file);
        } catch (const Error& err) {
            std::string text = err.what();
            std::string shown = displayPath(staging / file);
            if (text.compare(0, shown.size(), shown) == 0) text = e.rel + text.substr(shown.size());
            out.refused[file] = text;
            continue;
        }
        // What would not finish on a GPU, decided the same way on every machine.
        std::string source = readWholeFile(staging / file), biggest;
        int line = 0;
        constexpr double kMaxExpandedTokens = 1e6;  // a real exercise file expands to a few thousand
        if (macroExpansion(source, biggest, line, kMaxExpandedTokens) >= kMaxExpandedTokens) {
            out.refused[file] = file + ":" + std::to_string(line) + ": the macro " + biggest +
                                " expands to more than a million tokens (a macro bomb): refused before compiling";
        } else if (int loopLine = endlessLoopLine(source)) {
            out.endless[file] = file + ":" + std::to_string(loopLine) +
                                ": this loop never ends (its condition is always true and its body has no break, "
                                "return or discard): on a GPU the check would never finish";
        }
    }
    // Then the other shader files of the graded folder, where an #include finds them.
    std::set<const Item*> used;
    for (const auto& [file, c] : chosen) used.insert(c.item);
    const std::string prefix = root.empty() ? "" : root + "/";
    for (const Item& e : items) {
        if (used.count(&e) || hiddenPath(e.rel)) continue;
        bool inRoot = e.rel.compare(0, prefix.size(), prefix) == 0;
        const std::string rel = inRoot ? e.rel.substr(prefix.size()) : e.rel;
        bool exact = false;
        const bool exerciseCopy = exerciseNamed(nameOf(e.rel), exact) != nullptr;
        if (!inRoot || exerciseCopy) {
            if (!exerciseCopy) ignored.push_back(e.rel);
            continue;
        }
        // A folder named like an exercise file ("06-geometry.glsl/") must not become one.
        const std::string top = rel.substr(0, rel.find('/'));
        if (rel.find('/') != std::string::npos && exerciseNamed(top, exact)) {
            ignored.push_back(e.rel);
            continue;
        }
        if (e.type == Item::Type::Unextracted || !isShaderSource(lowerCase(rel))) {
            ignored.push_back(e.rel);
            continue;
        }
        if (e.type != Item::Type::File) {
            std::string why = !e.refusedWhy.empty()          ? e.refusedWhy
                              : e.type == Item::Type::Link ? "a symbolic link (links are never followed)"
                                                            : "not a regular file";
            refusedOther.push_back(e.rel + " (" + why + ")");
            continue;
        }
        if (e.size > kMaxShaderFileBytes) {
            refusedOther.push_back(e.rel + ": file is " + kib(e.size) + ", over the " + kib(kMaxShaderFileBytes) +
                                   " limit for a shader file");
            continue;
        }
        if (!fits(e.size)) {
            refusedOther.push_back(e.rel + " (over the limit of " + std::to_string(kMaxCopiedFiles) + " files)");
            continue;
        }
        std::string why;
        if (!copyRegularFile(e.source, staging / rel, why)) {
            refusedOther.push_back(e.rel + " (cannot be read: " + why + ")");
            continue;
        }
        ++copied;
        copiedBytes += e.size;
    }
    if (!refusedOther.empty()) out.notes.push_back("refused: " + listSome(refusedOther));
    // Every file that was not graded, those past the first 5,000 (counted, not listed) too.
    const std::size_t ignoredAll = ignored.size() + found.unlooked;
    if (ignoredAll)
        out.notes.push_back("ignored " + std::to_string(ignoredAll) + " file" + (ignoredAll == 1 ? "" : "s") +
                            " that " + (ignoredAll == 1 ? "is" : "are") + " not part of the exercises: " +
                            listSome(std::vector<std::string>(ignored.begin(), ignored.begin() + std::ptrdiff_t(std::min<std::size_t>(5, ignored.size())))) +
                            (ignoredAll > std::min<std::size_t>(5, ignored.size())
                                 ? " and " + std::to_string(ignoredAll - std::min<std::size_t>(5, ignored.size())) + " more"
                                 : ""));
}

}  // namespace

SubmissionList listSubmissions(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw Error(dir.string() + ": not a folder of submissions");
    std::vector<fs::directory_entry> entries;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) entries.push_back(*it);
    if (ec) throw Error(dir.string() + ": cannot be listed (" + ec.message() + ")");
    std::sort(entries.begin(), entries.end(),
              [](const fs::directory_entry& a, const fs::directory_entry& b) { return a.path() < b.path(); });

    SubmissionList list;
    std::set<std::string> taken;
    std::map<std::string, SubmissionEntry> groups;  // LMS downloads, by student
    for (const fs::directory_entry& entry : entries) {
        const std::string name = entry.path().filename().string();
        const std::string shown = safeEntryId(name);  // what JSON, HTML, CSV and the terminal get
        LmsDownloadName lms = parseLmsDownloadName(name);
        // A Moodle folder is named after the student's full name, which may begin with '.': graded.
        if (isHidden(name) && lms.kind != LmsDownloadName::Kind::Moodle) {
            list.ignored.push_back(shown + " (hidden)");
            continue;
        }
        fs::file_status st = entry.symlink_status(ec);
        // Canvas gives files only; a folder "lab_1_2_final" is a student's folder, not a download.
        const bool lmsPart = (lms.kind == LmsDownloadName::Kind::Canvas && fs::is_regular_file(st)) ||
                             (lms.kind == LmsDownloadName::Kind::Moodle && (fs::is_directory(st) || fs::is_regular_file(st)));
        if (lmsPart) {
            SubmissionEntry& g = groups[graderSafeId(safeEntryId(lms.student))];
            if (g.parts.empty()) {
                g.kind = SubmissionEntry::Kind::Group;
                g.path = entry.path();
            }
            g.parts.emplace_back(entry.path(), fs::is_directory(st) ? std::string() : lms.file);
            continue;
        }
        SubmissionEntry s;
        s.path = entry.path();
        if (fs::is_symlink(st)) {
            s.kind = SubmissionEntry::Kind::Link;
        } else if (fs::is_directory(st)) {
            s.kind = SubmissionEntry::Kind::Folder;
        } else if (fs::is_regular_file(st) && endsWithZip(name)) {
            s.kind = SubmissionEntry::Kind::Zip;
        } else {
            list.ignored.push_back(shown + (fs::is_regular_file(st) ? " (a file that is not a .zip, and not named as "
                                                                      "Canvas or Moodle name a student's file)"
                                                                    : " (not a folder, .zip or regular file)"));
            continue;
        }
        s.id = safeEntryId(s.kind != SubmissionEntry::Kind::Folder && endsWithZip(name) ? name.substr(0, name.size() - 4)
                                                                                         : name);
        if (taken.count(s.id)) s.id = shown;  // "alice" and "alice.zip": both graded, apart
        s.id = graderSafeId(s.id);             // a folder named "grades.csv": graded as "student-grades.csv"
        for (int k = 2; taken.count(s.id); ++k) s.id = graderSafeId(shown) + "-" + std::to_string(k);  // an escaped id met a real one
        taken.insert(s.id);
        list.students.push_back(s);
    }
    for (auto& [student, g] : groups) {
        g.id = student;
        for (int k = 2; taken.count(g.id); ++k) g.id = student + "-" + std::to_string(k);
        taken.insert(g.id);
        list.students.push_back(g);
    }
    std::sort(list.students.begin(), list.students.end(),
              [](const SubmissionEntry& a, const SubmissionEntry& b) { return a.id < b.id; });
    return list;
}

std::string submissionFingerprint(const SubmissionEntry& entry) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bit
    auto mix = [&h](const char* data, std::size_t n) {
        for (std::size_t k = 0; k < n; ++k) {
            h ^= static_cast<unsigned char>(data[k]);
            h *= 1099511628211ull;
        }
    };
    auto mixText = [&mix](const std::string& text) { mix(text.data(), text.size() + 1); };  // with its NUL
    std::uintmax_t budget = std::uintmax_t(64) << 20;
    auto mixFile = [&](const fs::path& path) {
        InputFile file(path, InputFile::Links::Refuse);
        if (!file.ok() || file.type() != fs::file_type::regular) return;
        mixText(std::to_string(file.size()));
        char buffer[65536];
        std::ptrdiff_t n;
        while (budget > 0 && (n = file.read(buffer, sizeof buffer)) > 0) {
            mix(buffer, std::size_t(n));
            budget -= std::min<std::uintmax_t>(budget, std::uintmax_t(n));
        }
    };
    std::error_code ec;
    if (entry.kind == SubmissionEntry::Kind::Group) {
        std::string parts;
        for (const auto& [path, name] : entry.parts) {
            SubmissionEntry one{name, path, fs::is_directory(fs::symlink_status(path, ec)) ? SubmissionEntry::Kind::Folder
                                                                                          : SubmissionEntry::Kind::Zip, {}};
            parts += path.filename().string() + ":" + submissionFingerprint(one) + ";";
        }
        mixText(parts);
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        return hex;
    }
    fs::file_status top = fs::symlink_status(entry.path, ec);
    if (fs::is_symlink(top)) {
        mixText("link:" + fs::read_symlink(entry.path, ec).string());
    } else if (fs::is_regular_file(top)) {
        mixFile(entry.path);
    } else {
        std::vector<std::pair<std::string, fs::path>> files;
        fs::recursive_directory_iterator it(entry.path, fs::directory_options::skip_permission_denied, ec), end;
        for (; !ec && it != end && files.size() <= kMaxListedEntries; it.increment(ec))
            files.emplace_back(it->path().lexically_relative(entry.path).generic_string(), it->path());
        std::sort(files.begin(), files.end());
        for (const auto& [rel, path] : files) {
            fs::file_status st = fs::symlink_status(path, ec);
            mixText(rel);
            if (fs::is_symlink(st))
                mixText("link:" + fs::read_symlink(path, ec).string());
            else if (fs::is_regular_file(st))
                mixFile(path);
            else
                mixText(fs::is_directory(st) ? "dir" : "other");
        }
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

StagedSubmission stageSubmission(const SubmissionEntry& entry, const fs::path& stagingDir, const fs::path& scratchDir) {
    StagedSubmission out;
    std::error_code ec;
    fs::create_directories(stagingDir, ec);
    const std::string shown = entry.kind == SubmissionEntry::Kind::Group ? entry.id : entry.path.filename().string();
    if (entry.kind == SubmissionEntry::Kind::Link) {
        out.problem = StagedSubmission::Problem::Refused;
        out.problemReason = "the submission " + shown + " is a symbolic link: refused, links are never followed";
        return out;
    }
    fs::remove_all(scratchDir, ec);
    fs::create_directories(scratchDir, ec);
    Collector found(scratchDir);
    if (entry.kind == SubmissionEntry::Kind::Zip) {
        found.zip(entry.path, "", 1);
    } else if (entry.kind == SubmissionEntry::Kind::Folder) {
        found.folder(entry.path, "", 0);
    } else {
        // An LMS download: each part under the name it stands for.
        for (const auto& [path, name] : entry.parts) {
            fs::file_status st = fs::symlink_status(path, ec);
            if (fs::is_directory(st)) {
                found.folder(path, "", 0);
            } else if (fs::is_regular_file(st) && endsWithZip(name)) {
                found.zip(path, name + "/", 1);
            } else {
                Item::Type type = fs::is_symlink(st)        ? Item::Type::Link
                                  : fs::is_regular_file(st) ? Item::Type::File
                                                            : Item::Type::Other;
                found.items.push_back({type, name, path, type == Item::Type::File ? fs::file_size(path, ec) : 0, ""});
            }
        }
        out.notes.push_back("graded the files " + listSome([&] {
                                std::vector<std::string> names;
                                for (const auto& part : entry.parts) names.push_back(safeEntryId(part.first.filename().string()));
                                return names;
                            }()) + " of the LMS download as one submission");
    }
    out.notes.insert(out.notes.end(), found.notes.begin(), found.notes.end());
    if (!found.overLimit.empty()) {
        out.problem = StagedSubmission::Problem::Refused;
        out.problemReason = found.overLimit;
        fs::remove_all(scratchDir, ec);
        return out;
    }
    stageItems(found.items, found, stagingDir, shown, out);
    fs::remove_all(scratchDir, ec);
    return out;
}

}  // namespace rl
