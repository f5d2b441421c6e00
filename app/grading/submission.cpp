#include "grading/submission.h"

#include "checks/exercise_registry.h"
#include "core/error.h"
#include "grading/safe_unzip.h"
#include "shader/source_assembler.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace rl {

namespace {

// Names the grader writes beside the students' folders in OUT.
const std::set<std::string> kReservedIds = {"grades.csv", "index.html", "summary.json", "rubric.json", "_reference"};

// Limits on what is copied from one submission: far above a real one.
constexpr std::size_t kMaxWalkedEntries = 5000;
constexpr int kMaxWalkDepth = 6;
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

const std::set<std::string>& exerciseFiles() {
    static const std::set<std::string> files = [] {
        std::set<std::string> s;
        for (const ExerciseInfo& e : allExercises()) s.insert(e.file());
        return s;
    }();
    return files;
}

std::string listSome(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t k = 0; k < names.size() && k < 5; ++k) out += (k ? ", " : "") + names[k];
    if (names.size() > 5) out += " and " + std::to_string(names.size() - 5) + " more";
    return out;
}

std::string kib(std::uintmax_t bytes) { return std::to_string((bytes + 1023) / 1024) + " KiB"; }

// One entry of the submitted tree, as lstat sees it (links are never followed).
struct TreeEntry {
    enum class Type { File, Dir, Link, Other } type;
    std::string rel;  // generic path relative to the submission
    std::uintmax_t size = 0;
    std::string refusedWhy;  // set for entries refused before staging (zip links)
};

std::string parentOf(const std::string& rel) {
    auto slash = rel.rfind('/');
    return slash == std::string::npos ? "" : rel.substr(0, slash);
}

std::string nameOf(const std::string& rel) {
    auto slash = rel.rfind('/');
    return slash == std::string::npos ? rel : rel.substr(slash + 1);
}

int depthOf(const std::string& rel) { return rel.empty() ? 0 : int(std::count(rel.begin(), rel.end(), '/')) + 1; }

std::vector<TreeEntry> walk(const fs::path& root, std::vector<std::string>& notes) {
    std::vector<TreeEntry> out;
    std::error_code ec;
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
    if (ec) {
        notes.push_back("the submission cannot be listed (" + ec.message() + ")");
        return out;
    }
    for (; it != end; it.increment(ec)) {
        if (ec) break;
        if (out.size() >= kMaxWalkedEntries) {
            notes.push_back("the submission holds more than " + std::to_string(kMaxWalkedEntries) +
                            " files; the rest were not looked at");
            break;
        }
        const fs::path& p = it->path();
        std::string rel = p.lexically_relative(root).generic_string();
        fs::file_status st = it->symlink_status(ec);
        TreeEntry e{TreeEntry::Type::Other, rel, 0, ""};
        if (fs::is_symlink(st)) {
            e.type = TreeEntry::Type::Link;
        } else if (fs::is_directory(st)) {
            e.type = TreeEntry::Type::Dir;
            if (isHidden(p.filename().string()) || it.depth() + 1 >= kMaxWalkDepth) it.disable_recursion_pending();
        } else if (fs::is_regular_file(st)) {
            e.type = TreeEntry::Type::File;
            e.size = it->file_size(ec);
        }
        out.push_back(e);
    }
    return out;
}

// Copies a regular file without following links or blocking on special files.
bool copyRegularFile(const fs::path& from, const fs::path& to, std::string& why) {
    int in = open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (in < 0) {
        why = std::strerror(errno);
        return false;
    }
    struct stat st;
    if (fstat(in, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(in);
        why = "not a regular file";
        return false;
    }
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    int outFd = open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (outFd < 0) {
        why = std::strerror(errno);
        close(in);
        return false;
    }
    char buffer[65536];
    bool ok = true;
    for (;;) {
        ssize_t n = read(in, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            why = std::strerror(errno);
            ok = false;
            break;
        }
        if (n == 0) break;
        if (write(outFd, buffer, std::size_t(n)) != n) {
            why = std::strerror(errno);
            ok = false;
            break;
        }
    }
    close(in);
    close(outFd);
    return ok;
}

// Stages the tree at `source` (a folder, or a zip's extracted contents).
void stageTree(const fs::path& source, const std::map<std::string, std::string>& zipRefused, const fs::path& staging,
               const std::string& shownName, StagedSubmission& out) {
    std::vector<TreeEntry> tree = walk(source, out.notes);
    for (const auto& [rel, why] : zipRefused) tree.push_back({TreeEntry::Type::Link, rel, 0, why});

    bool anyFile = std::any_of(tree.begin(), tree.end(), [](const TreeEntry& e) {
        return e.type != TreeEntry::Type::Dir && !isHidden(nameOf(e.rel));
    });
    if (!anyFile) {
        out.problem = StagedSubmission::Problem::Empty;
        out.problemReason = "the submission is empty: " + shownName + " holds no files to grade";
        return;
    }

    // The folder that holds the exercise files: the top, or the shallowest
    // folder (at most two levels down) holding any of them.
    std::map<std::string, int> found;  // folder -> exercise files in it
    for (const TreeEntry& e : tree)
        if (e.type != TreeEntry::Type::Dir && exerciseFiles().count(nameOf(e.rel)) && depthOf(parentOf(e.rel)) <= 2) {
            bool hidden = false;
            for (std::string d = parentOf(e.rel); !d.empty(); d = parentOf(d)) hidden = hidden || isHidden(nameOf(d));
            if (!hidden) ++found[parentOf(e.rel)];
        }
    if (found.empty()) {
        std::vector<std::string> names;
        for (const TreeEntry& e : tree)
            if (e.type != TreeEntry::Type::Dir) names.push_back(e.rel);
        out.problem = StagedSubmission::Problem::Empty;
        out.problemReason = "no exercise files (01-camera.glsl ... 10-display.glsl) in the submission " + shownName +
                            "; it holds " + listSome(names);
        return;
    }
    std::string root;
    int bestDepth = 99, bestCount = 0;
    for (const auto& [folder, count] : found) {  // std::map: ties go to the first name
        int depth = depthOf(folder);
        if (depth < bestDepth || (depth == bestDepth && count > bestCount)) {
            root = folder;
            bestDepth = depth;
            bestCount = count;
        }
    }
    if (!root.empty()) out.notes.push_back("graded the folder " + root + "/ inside the submission");
    if (found.size() > 1) {
        std::vector<std::string> others;
        for (const auto& [folder, count] : found)
            if (folder != root) others.push_back((folder.empty() ? "." : folder) + "/");
        out.notes.push_back("exercise files in other folders were ignored: " + listSome(others));
    }

    std::vector<std::string> ignored, refusedOther;
    std::size_t copied = 0;
    std::uintmax_t copiedBytes = 0;
    const std::string prefix = root.empty() ? "" : root + "/";
    for (const TreeEntry& e : tree) {
        if (e.type == TreeEntry::Type::Dir) continue;
        if (e.rel.compare(0, prefix.size(), prefix) != 0) {
            if (!isHidden(nameOf(e.rel))) ignored.push_back(e.rel);
            continue;
        }
        const std::string rel = e.rel.substr(prefix.size());
        const bool exercise = rel.find('/') == std::string::npos && exerciseFiles().count(rel);
        bool hidden = false;
        for (std::string d = rel; !d.empty(); d = parentOf(d)) hidden = hidden || isHidden(nameOf(d));
        if (hidden) continue;
        if (e.type == TreeEntry::Type::Link || e.type == TreeEntry::Type::Other) {
            std::string why = !e.refusedWhy.empty()                 ? e.refusedWhy
                              : e.type == TreeEntry::Type::Link ? "a symbolic link (links are never followed)"
                                                                : "not a regular file";
            if (exercise)
                out.refused[rel] = rel + " is " + why + ": refused, grading reads only regular files inside your own submission";
            else
                refusedOther.push_back(rel + " (" + why + ")");
            continue;
        }
        if (!exercise && !isShaderSource(rel)) {
            ignored.push_back(rel);
            continue;
        }
        if (e.size > kMaxShaderFileBytes) {
            std::string why = rel + ": file is " + kib(e.size) + ", over the " + kib(kMaxShaderFileBytes) +
                              " limit for a shader file";
            if (exercise)
                out.refused[rel] = why;
            else
                refusedOther.push_back(why);
            continue;
        }
        if (copied >= kMaxCopiedFiles || copiedBytes + e.size > kMaxCopiedBytes) {
            if (exercise)
                out.refused[rel] = rel + ": not read, the submission holds too many shader files";
            else
                refusedOther.push_back(rel + " (over the limit of " + std::to_string(kMaxCopiedFiles) + " files)");
            continue;
        }
        std::string why;
        if (!copyRegularFile(source / e.rel, staging / rel, why)) {
            if (exercise)
                out.refused[rel] = rel + ": cannot be read (" + why + ")";
            else
                refusedOther.push_back(rel + " (cannot be read: " + why + ")");
            continue;
        }
        ++copied;
        copiedBytes += e.size;
        if (exercise) {
            // The checks the shader assembler makes on every file (size, UTF-8, NUL
            // bytes), here, so that the reason names the student's own file.
            try {
                readSourceFile(staging / rel);
            } catch (const Error& err) {
                std::string text = err.what();
                std::string shown = displayPath(staging / rel);
                if (text.compare(0, shown.size(), shown) == 0) text = rel + text.substr(shown.size());
                out.refused[rel] = text;
            }
        }
    }
    if (!refusedOther.empty()) out.notes.push_back("refused: " + listSome(refusedOther));
    if (!ignored.empty())
        out.notes.push_back("ignored " + std::to_string(ignored.size()) + " file" + (ignored.size() == 1 ? "" : "s") +
                            " that " + (ignored.size() == 1 ? "is" : "are") + " not part of the exercises: " +
                            listSome(ignored));
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
    for (const fs::directory_entry& entry : entries) {
        const std::string name = entry.path().filename().string();
        if (isHidden(name)) {
            list.ignored.push_back(name + " (hidden)");
            continue;
        }
        fs::file_status st = entry.symlink_status(ec);
        SubmissionEntry s;
        s.path = entry.path();
        if (fs::is_symlink(st)) {
            s.kind = SubmissionEntry::Kind::Link;
        } else if (fs::is_directory(st)) {
            s.kind = SubmissionEntry::Kind::Folder;
        } else if (fs::is_regular_file(st) && endsWithZip(name)) {
            s.kind = SubmissionEntry::Kind::Zip;
        } else {
            list.ignored.push_back(name + " (not a folder or .zip)");
            continue;
        }
        s.id = s.kind != SubmissionEntry::Kind::Folder && endsWithZip(name) ? name.substr(0, name.size() - 4) : name;
        if (taken.count(s.id)) s.id = name;  // "alice" and "alice.zip": both graded, apart
        if (kReservedIds.count(s.id)) {
            list.ignored.push_back(name + " (its name is one of the grader's own outputs: rename it)");
            continue;
        }
        taken.insert(s.id);
        list.students.push_back(s);
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
        int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return;
        struct stat st;
        if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
            mixText(std::to_string(st.st_size));
            char buffer[65536];
            ssize_t n;
            while (budget > 0 && (n = read(fd, buffer, sizeof buffer)) > 0) {
                mix(buffer, std::size_t(n));
                budget -= std::min<std::uintmax_t>(budget, std::uintmax_t(n));
            }
        }
        close(fd);
    };
    std::error_code ec;
    fs::file_status top = fs::symlink_status(entry.path, ec);
    if (fs::is_symlink(top)) {
        mixText("link:" + fs::read_symlink(entry.path, ec).string());
    } else if (fs::is_regular_file(top)) {
        mixFile(entry.path);
    } else {
        std::vector<std::pair<std::string, fs::path>> files;
        fs::recursive_directory_iterator it(entry.path, fs::directory_options::skip_permission_denied, ec), end;
        for (; !ec && it != end && files.size() < kMaxWalkedEntries; it.increment(ec))
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
    const std::string shown = entry.path.filename().string();
    if (entry.kind == SubmissionEntry::Kind::Link) {
        out.problem = StagedSubmission::Problem::Refused;
        out.problemReason = "the submission " + shown + " is a symbolic link: refused, links are never followed";
        return out;
    }
    fs::path source = entry.path;
    std::map<std::string, std::string> zipRefused;
    fs::path zip = entry.kind == SubmissionEntry::Kind::Zip ? entry.path : fs::path();
    if (zip.empty()) {
        // A folder that holds nothing but one zip (a Gradescope upload): grade the zip.
        std::vector<fs::path> files;
        for (fs::directory_iterator it(entry.path, ec), end; !ec && it != end; it.increment(ec))
            if (!isHidden(it->path().filename().string())) files.push_back(it->path());
        if (files.size() == 1 && fs::is_regular_file(fs::symlink_status(files[0], ec)) &&
            endsWithZip(files[0].filename().string())) {
            zip = files[0];
            out.notes.push_back("graded the zip " + zip.filename().string() + " inside the submission");
        }
    }
    if (!zip.empty()) {
        fs::remove_all(scratchDir, ec);
        try {
            zipRefused = extractZipSafely(zip, scratchDir).refused;
        } catch (const Error& e) {
            out.problem = StagedSubmission::Problem::Refused;
            out.problemReason = std::string("the submission was refused: ") + e.what();
            return out;
        }
        source = scratchDir;
    }
    stageTree(source, zipRefused, stagingDir, shown, out);
    if (!zip.empty()) fs::remove_all(scratchDir, ec);
    return out;
}

}  // namespace rl
