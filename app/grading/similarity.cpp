#include "grading/similarity.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace rl {

namespace {

// k-grams of 12 tokens (about one GLSL statement), winnowed with a window of
// 8: any run of 12 + 8 - 1 = 19 shared tokens is always found, as in Dolos's
// defaults (k 23, w 17 on AST tokens, which are finer than GLSL's lexemes).
constexpr std::size_t kGram = 12;
constexpr std::size_t kWindow = 8;
// Two files are joined from this share of the smaller file's evidence and
// at least kMinShared shared fingerprints: half of one file, and more than a
// short function (a finished exercise has 30 to 200 fingerprints; a
// one-line exercise 5 to 10, so two identical one-liners are never evidence).
constexpr double kMinSimilarity = 0.5;
constexpr std::size_t kMinShared = 8;
// Fingerprints held by more than this share of the class's files of an
// exercise are common code (Dolos's maxFingerprintPercentage), not evidence.
constexpr double kCommonShare = 0.2;
constexpr std::size_t kMaxLines = 12;

// GLSL's own words: kept as they are when identifiers are normalised.
const std::unordered_set<std::string>& glslWords() {
    static const std::unordered_set<std::string> words = {
        // keywords and qualifiers
        "attribute", "const", "uniform", "varying", "buffer", "shared", "centroid", "flat", "smooth", "layout",
        "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else", "in", "out", "inout",
        "true", "false", "invariant", "discard", "return", "struct", "precision", "highp", "mediump", "lowp",
        // types
        "void", "bool", "int", "uint", "float", "double", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2",
        "uvec3", "uvec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2",
        "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "sampler2D", "samplerCube", "sampler3D",
        // built-in functions
        "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "pow", "exp",
        "log", "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "trunc", "round", "ceil", "fract",
        "mod", "modf", "min", "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "length", "distance",
        "dot", "cross", "normalize", "faceforward", "reflect", "refract", "matrixCompMult", "transpose", "inverse",
        "determinant", "lessThan", "greaterThan", "equal", "notEqual", "any", "all", "not", "texture", "textureLod",
        "texelFetch", "textureSize", "dFdx", "dFdy", "fwidth", "gl_FragCoord", "gl_FragColor"};
    return words;
}

struct Tok {
    std::string text;  // normalised
    std::string raw;
    int line;
};

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// GLSL tokens outside comments and preprocessor lines, with their lines;
// `normalise`: identifiers that are not GLSL's own (nor a swizzle after '.') become "$".
std::vector<Tok> tokens(const std::string& s, bool normalise) {
    static const char* const kTwo[] = {"==", "!=", "<=", ">=", "&&", "||", "^^", "+=", "-=", "*=", "/=", "++", "--",
                                       "<<", ">>", "%=", "&=", "|="};
    std::vector<Tok> out;
    int line = 1;
    bool lineStart = true;
    for (std::size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\n') {
            ++line;
            ++i;
            lineStart = true;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            std::size_t end = s.find("*/", i + 2);
            end = end == std::string::npos ? s.size() : end + 2;
            line += int(std::count(s.begin() + std::ptrdiff_t(i), s.begin() + std::ptrdiff_t(end), '\n'));
            i = end;
            continue;
        }
        if (lineStart && c == '#') {  // a directive: not the student's logic
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        lineStart = false;
        const std::size_t start = i;
        bool ident = false;
        if (identStart(c)) {
            while (i < s.size() && identChar(s[i])) ++i;
            ident = true;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            while (i < s.size() && (identChar(s[i]) || s[i] == '.')) ++i;
        } else {
            i += 1;
            for (const char* two : kTwo)
                if (s.compare(start, 2, two) == 0) i = start + 2;
        }
        Tok t;
        t.raw = s.substr(start, i - start);
        t.line = line;
        const bool swizzle = !out.empty() && out.back().raw == ".";
        t.text = normalise && ident && !swizzle && !glslWords().count(t.raw) ? "$" : t.raw;
        out.push_back(std::move(t));
    }
    return out;
}

std::uint64_t fnv(const std::string& text, std::uint64_t h = 1469598103934665603ull) {
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

struct Print {
    std::uint64_t hash;
    int line;  // first line of its k-gram
};

// Winnowing of one unit: the smallest k-gram hash of every window (rightmost on ties).
void winnowUnit(const std::vector<Tok>& t, std::size_t from, std::size_t to, std::vector<Print>& out) {
    std::vector<Print> grams;
    if (to - from < kGram) {
        // A unit shorter than a k-gram (a one-line function) is one fingerprint of its own.
        if (to - from >= 4) {
            std::uint64_t h = fnv("short");
            for (std::size_t j = from; j < to; ++j) h = fnv(t[j].text + "\x1f", h);
            out.push_back({h, t[from].line});
        }
        return;
    }
    for (std::size_t k = from; k + kGram <= to; ++k) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::size_t j = k; j < k + kGram; ++j) h = fnv(t[j].text + "\x1f", h);
        grams.push_back({h, t[k].line});
    }
    const std::size_t windows = grams.size() > kWindow ? grams.size() - kWindow + 1 : 1;
    std::size_t last = grams.size();
    for (std::size_t w = 0; w < windows; ++w) {
        std::size_t best = w;
        for (std::size_t j = w; j < std::min(grams.size(), w + kWindow); ++j)
            if (grams[j].hash <= grams[best].hash) best = j;
        if (best != last) out.push_back(grams[best]);
        last = best;
    }
}

// The fingerprints of a file, unit by unit: a unit is a top-level function
// (its header and body) or declaration, so the order of the units does not
// change the set.
std::vector<Print> fingerprints(const std::string& text) {
    const std::vector<Tok> t = tokens(text, true);
    std::vector<Print> out;
    std::size_t unitStart = 0;
    int depth = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const std::string& x = t[k].raw;
        if (x == "{" || x == "(" || x == "[") ++depth;
        if (x == "}" || x == ")" || x == "]") depth = std::max(0, depth - 1);
        const bool ends = depth == 0 && (x == ";" || (x == "}" && !(k + 1 < t.size() && t[k + 1].raw == ";")));
        if (ends) {
            winnowUnit(t, unitStart, k + 1, out);
            unitStart = k + 1;
        }
    }
    if (unitStart < t.size()) winnowUnit(t, unitStart, t.size(), out);
    return out;
}

std::string trim(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (;;) {
        std::size_t nl = text.find('\n', from);
        out.push_back(text.substr(from, nl == std::string::npos ? std::string::npos : nl - from));
        if (nl == std::string::npos) break;
        from = nl + 1;
    }
    return out;
}

// Files of one exercise with the same text after comments and white space.
struct Group {
    std::vector<std::size_t> members;        // indices into the exercise's files
    std::vector<Print> prints;               // of the text, base code left out
    std::vector<std::uint64_t> evidence;     // distinct hashes of `prints` outside common code, sorted
};

struct Found {  // a cluster of one exercise
    std::set<std::string> students;
    bool identical = false;
    std::size_t evidence = 0;
    double similarity = 0;
    std::string exercise, a, b;
    std::vector<SharedLine> lines;
    std::vector<SimilarPair> pairs;
};

struct UnionFind {
    std::vector<std::size_t> up;
    explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
    std::size_t find(std::size_t x) {
        while (up[x] != x) x = up[x] = up[up[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) { up[find(a)] = find(b); }
};

// The lines of A whose fingerprints B holds, beside B's line of the same fingerprint.
std::vector<SharedLine> sharedLines(const SimilarityFile& fa, const std::vector<Print>& pa, const std::vector<Print>& pb,
                                    const std::unordered_set<std::uint64_t>& evidence) {
    std::unordered_map<std::uint64_t, int> lineInB;
    for (const Print& p : pb) lineInB.emplace(p.hash, p.line);
    const std::vector<std::string> la = linesOf(fa.text);
    std::vector<SharedLine> out;
    std::set<int> seen;
    for (const Print& p : pa) {
        auto it = lineInB.find(p.hash);
        if (it == lineInB.end() || !evidence.count(p.hash) || !seen.insert(p.line).second) continue;
        std::string text = p.line >= 1 && std::size_t(p.line) <= la.size() ? trim(la[std::size_t(p.line) - 1]) : "";
        if (text.size() > 160) text = text.substr(0, 160) + "...";
        out.push_back({p.line, it->second, text});
        if (out.size() >= kMaxLines) break;
    }
    return out;
}

std::vector<Found> clustersOfExercise(const std::string& exercise, std::vector<const SimilarityFile*> list,
                                      const std::vector<SimilarityFile>& base) {
    std::sort(list.begin(), list.end(),
              [](const SimilarityFile* a, const SimilarityFile* b) { return a->student < b->student; });
    std::unordered_set<std::uint64_t> basePrints;
    std::set<std::string> baseNormal;
    for (const SimilarityFile& s : base)
        if (s.exercise == exercise) {
            for (const Print& p : fingerprints(s.text)) basePrints.insert(p.hash);
            baseNormal.insert(withoutCommentsOrSpacing(s.text));
        }
    // Identical files become one group: a class of 300 with one short file is one comparison.
    std::map<std::string, std::size_t> groupOf;
    std::vector<Group> groups;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string n = withoutCommentsOrSpacing(list[k]->text);
        if (n.empty() || baseNormal.count(n)) continue;  // the stub or the solution itself: no evidence
        auto [it, fresh] = groupOf.emplace(n, groups.size());
        if (fresh) {
            groups.emplace_back();
            for (const Print& p : fingerprints(list[k]->text))
                if (!basePrints.count(p.hash)) groups.back().prints.push_back(p);
        }
        groups[it->second].members.push_back(k);
    }
    // Common code: fingerprints held by more than kCommonShare of the class's files (at
    // least 4 files, so that a small class, or a test, still sees a copy shared by three).
    const std::size_t common = std::max<std::size_t>(4, std::size_t(std::ceil(kCommonShare * double(list.size()))));
    std::unordered_map<std::uint64_t, std::size_t> holders;
    for (Group& g : groups) {
        std::set<std::uint64_t> distinct;
        for (const Print& p : g.prints) distinct.insert(p.hash);
        g.evidence.assign(distinct.begin(), distinct.end());
        for (std::uint64_t h : g.evidence) holders[h] += g.members.size();
    }
    std::unordered_set<std::uint64_t> evidence;
    for (Group& g : groups) {
        std::vector<std::uint64_t> kept;
        for (std::uint64_t h : g.evidence)
            if (holders[h] <= common) kept.push_back(h);
        g.evidence = kept;
        evidence.insert(kept.begin(), kept.end());
    }
    // Shared evidence between groups: every fingerprint's owners, pair by pair
    // (each fingerprint has at most `common` owners, so this is bounded).
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> owners;
    for (std::size_t k = 0; k < groups.size(); ++k)
        for (std::uint64_t h : groups[k].evidence) owners[h].push_back(k);
    std::unordered_map<std::uint64_t, std::size_t> shared;  // (i * groups + j) -> count
    for (const auto& [hash, who] : owners)
        for (std::size_t i = 0; i < who.size(); ++i)
            for (std::size_t j = i + 1; j < who.size(); ++j) ++shared[std::uint64_t(who[i]) * groups.size() + who[j]];

    UnionFind uf(groups.size());
    std::vector<bool> inCluster(groups.size(), false);
    // The strongest link of each component: (evidence, similarity, group a, group b).
    struct Link {
        std::size_t n = 0;
        double share = 0;
        std::size_t a = 0, b = 0;
    };
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t, double>> links;  // a, b, n, share
    for (const auto& [key, n] : shared) {
        const std::size_t a = std::size_t(key / groups.size()), b = std::size_t(key % groups.size());
        const std::size_t smaller = std::min(groups[a].evidence.size(), groups[b].evidence.size());
        const double share = smaller ? double(n) / double(smaller) : 0.0;
        if (n >= kMinShared && share >= kMinSimilarity) links.emplace_back(a, b, n, share);
    }
    std::sort(links.begin(), links.end());  // the same bytes from the same class, whatever the hash order
    for (const auto& [a, b, n, share] : links) {
        uf.join(a, b);
        inCluster[a] = inCluster[b] = true;
    }
    for (std::size_t k = 0; k < groups.size(); ++k)
        if (groups[k].members.size() >= 2 && groups[k].evidence.size() >= kMinShared) inCluster[k] = true;

    std::map<std::size_t, Link> best;  // root -> strongest link
    std::map<std::size_t, std::vector<std::size_t>> parts;
    for (std::size_t k = 0; k < groups.size(); ++k)
        if (inCluster[k]) parts[uf.find(k)].push_back(k);
    for (const auto& [a, b, n, share] : links) {
        Link& l = best[uf.find(a)];
        if (n > l.n || (n == l.n && share > l.share)) l = {n, share, a, b};
    }
    std::vector<Found> out;
    for (const auto& [root, members] : parts) {
        Found f;
        f.exercise = exercise;
        for (std::size_t g : members)
            for (std::size_t k : groups[g].members) f.students.insert(list[k]->student);
        if (f.students.size() < 2) continue;
        f.identical = members.size() == 1;
        std::size_t ga, gb;
        const SimilarityFile *fa, *fb;
        if (f.identical) {
            ga = gb = members[0];
            fa = list[groups[ga].members[0]];
            fb = list[groups[ga].members[1]];
            f.evidence = groups[ga].evidence.size();
            f.similarity = 1.0;
        } else {
            const Link& l = best[root];
            ga = l.a;
            gb = l.b;
            fa = list[groups[ga].members[0]];
            fb = list[groups[gb].members[0]];
            f.evidence = l.n;
            f.similarity = std::round(l.share * 1000.0) / 1000.0;
        }
        f.a = fa->student;
        f.b = fb->student;
        for (const auto& [la, lb, n, share] : links)
            if (uf.find(la) == root) {
                std::string x = list[groups[la].members[0]]->student, y = list[groups[lb].members[0]]->student;
                if (y < x) std::swap(x, y);
                f.pairs.push_back({exercise, x, y, n, std::round(share * 1000.0) / 1000.0});
            }
        std::stable_sort(f.pairs.begin(), f.pairs.end(), [](const SimilarPair& p, const SimilarPair& q) {
            return p.evidence != q.evidence ? p.evidence > q.evidence : std::tie(p.a, p.b) < std::tie(q.a, q.b);
        });
        if (f.pairs.size() > kMaxClusterPairs) f.pairs.resize(kMaxClusterPairs);
        f.lines = sharedLines(*fa, groups[ga].prints, groups[gb].prints, evidence);
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace

std::string withoutCommentsOrSpacing(const std::string& text) {
    std::string out;
    for (const Tok& t : tokens(text, false)) out += (out.empty() ? "" : " ") + t.raw;
    // Directives count too: the same code with another #define is not the same file.
    for (const std::string& l : linesOf(text)) {
        const std::string t = trim(l);
        if (!t.empty() && t[0] == '#') out += "\n" + t;
    }
    return out;
}

std::string normalisedTokens(const std::string& text) {
    std::string out;
    for (const Tok& t : tokens(text, true)) out += (out.empty() ? "" : " ") + t.text;
    return out;
}

SimilarityReport findSimilarSubmissions(const std::vector<SimilarityFile>& files,
                                        const std::vector<SimilarityFile>& base, std::size_t limit) {
    std::map<std::string, std::vector<const SimilarityFile*>> byExercise;
    for (const SimilarityFile& f : files) byExercise[f.exercise].push_back(&f);
    // One entry per set of students: the exercises where they share code, together.
    std::map<std::set<std::string>, SimilarCluster> bySet;
    std::map<std::set<std::string>, std::size_t> strongest;  // the evidence of the entry's example
    for (const auto& [exercise, list] : byExercise)
        for (Found& f : clustersOfExercise(exercise, list, base)) {
            auto [it, fresh] = bySet.emplace(f.students, SimilarCluster{});
            SimilarCluster& c = it->second;
            if (fresh) {
                c.students.assign(f.students.begin(), f.students.end());
                c.studentCount = c.students.size();
                if (c.students.size() > kMaxClusterStudents) c.students.resize(kMaxClusterStudents);
                c.identical = true;
            }
            c.exercises.push_back(exercise);
            for (const SimilarPair& p : f.pairs)
                if (c.pairs.size() < kMaxClusterPairs) c.pairs.push_back(p);
            c.identical = c.identical && f.identical;
            c.evidence += f.evidence;
            c.similarity = std::max(c.similarity, f.similarity);
            if (fresh || f.evidence > strongest[f.students]) {
                strongest[f.students] = f.evidence;
                c.exercise = f.exercise;
                c.a = f.a;
                c.b = f.b;
                c.lines = std::move(f.lines);
            }
        }
    SimilarityReport report;
    report.filesCompared = files.size();
    for (auto& [set, c] : bySet) report.clusters.push_back(std::move(c));
    std::stable_sort(report.clusters.begin(), report.clusters.end(), [](const SimilarCluster& x, const SimilarCluster& y) {
        if (x.evidence != y.evidence) return x.evidence > y.evidence;
        if (x.similarity != y.similarity) return x.similarity > y.similarity;
        return x.students < y.students;
    });
    report.clustersFound = report.clusters.size();
    if (report.clusters.size() > limit) report.clusters.resize(limit);
    return report;
}

nlohmann::json toJson(const SimilarityReport& report) {
    nlohmann::json clusters = nlohmann::json::array();
    for (const SimilarCluster& c : report.clusters) {
        nlohmann::json lines = nlohmann::json::array();
        for (const SharedLine& l : c.lines) lines.push_back({{"line_a", l.lineA}, {"line_b", l.lineB}, {"text", l.text}});
        nlohmann::json pairs = nlohmann::json::array();
        for (const SimilarPair& p : c.pairs)
            pairs.push_back({{"exercise", p.exercise}, {"a", p.a}, {"b", p.b}, {"evidence", p.evidence},
                             {"similarity", p.similarity}});
        clusters.push_back({{"students", c.students},
                            {"pairs", pairs},
                            {"student_count", c.studentCount},
                            {"exercises", c.exercises},
                            {"kind", c.identical ? "identical" : "similar"},
                            {"evidence", c.evidence},
                            {"similarity", c.similarity},
                            {"example", {{"exercise", c.exercise}, {"a", c.a}, {"b", c.b}, {"shared_lines", lines}}}});
    }
    return {{"clusters", clusters},
            {"clusters_found", report.clustersFound},
            {"clusters_listed", report.clusters.size()},
            {"files_compared", report.filesCompared},
            {"rule",
             "fingerprints of the stub and the solution, and those held by more than 20% of the class's files of an "
             "exercise (at least 4), are base code; files joined from 8 shared fingerprints and half of the smaller "
             "file's; identifiers normalised, functions compared in any order"}};
}

}  // namespace rl
