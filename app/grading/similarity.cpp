#include "grading/similarity.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace rl {

namespace {

// k-grams of 12 tokens (about one GLSL statement), winnowed with a window of
// 8: any run of 12 + 8 - 1 = 19 shared tokens is always found, as in Dolos's
// defaults (k 23, w 17 on AST tokens, which are finer than GLSL's lexemes).
constexpr std::size_t kGram = 12;
constexpr std::size_t kWindow = 8;
// A pair is "similar" from this share of the smaller file's fingerprints and
// at least kMinShared of them: 80% of one file, and more than a short
// function (a finished exercise has 30 to 200 fingerprints).
constexpr double kMinSimilarity = 0.8;
constexpr std::size_t kMinShared = 10;
// Fingerprints found in more than this share of the class's files of an
// exercise are common code (Dolos's maxFingerprintPercentage), not evidence.
constexpr double kCommonShare = 0.2;

struct Tok {
    std::string text;
    int line;
};

// GLSL tokens outside comments and preprocessor lines, with their lines.
std::vector<Tok> tokens(const std::string& s) {
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
        std::size_t start = i;
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.') {
            while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_' || s[i] == '.')) ++i;
        } else {
            ++i;
        }
        out.push_back({s.substr(start, i - start), line});
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
    int lastLine;
};

// Winnowing: the smallest k-gram hash of every window (rightmost on ties), each kept once.
std::vector<Print> winnow(const std::vector<Tok>& t) {
    std::vector<Print> grams;
    if (t.size() < kGram) return grams;
    for (std::size_t k = 0; k + kGram <= t.size(); ++k) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::size_t j = k; j < k + kGram; ++j) h = fnv(t[j].text + "\x1f", h);
        grams.push_back({h, t[k].line, t[k + kGram - 1].line});
    }
    std::vector<Print> out;
    const std::size_t windows = grams.size() > kWindow ? grams.size() - kWindow + 1 : 1;
    std::size_t last = grams.size();
    for (std::size_t w = 0; w < windows; ++w) {
        std::size_t best = w;
        for (std::size_t j = w; j < std::min(grams.size(), w + kWindow); ++j)
            if (grams[j].hash <= grams[best].hash) best = j;
        if (best != last) out.push_back(grams[best]);
        last = best;
    }
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

}  // namespace

std::string withoutCommentsOrSpacing(const std::string& text) {
    std::string out;
    for (const Tok& t : tokens(text)) out += (out.empty() ? "" : " ") + t.text;
    // Directives count too: the same code with another #define is not the same file.
    for (const std::string& l : linesOf(text)) {
        const std::string t = trim(l);
        if (!t.empty() && t[0] == '#') out += "\n" + t;
    }
    return out;
}

std::vector<SimilarPair> findSimilarSubmissions(const std::vector<SimilarityFile>& files,
                                                const std::vector<SimilarityFile>& stubs) {
    std::map<std::string, std::vector<const SimilarityFile*>> byExercise;
    for (const SimilarityFile& f : files) byExercise[f.exercise].push_back(&f);
    std::vector<SimilarPair> pairs;
    for (auto& [exercise, list] : byExercise) {
        std::unordered_set<std::uint64_t> stubPrints;
        std::string stubNormal;
        for (const SimilarityFile& s : stubs)
            if (s.exercise == exercise) {
                for (const Print& p : winnow(tokens(s.text))) stubPrints.insert(p.hash);
                stubNormal = withoutCommentsOrSpacing(s.text);
            }
        std::sort(list.begin(), list.end(),
                  [](const SimilarityFile* a, const SimilarityFile* b) { return a->student < b->student; });
        // Identical after normalisation (the stub itself is no evidence).
        std::map<std::string, std::vector<std::size_t>> same;
        std::vector<std::vector<Print>> prints(list.size());
        std::unordered_map<std::uint64_t, std::vector<std::size_t>> owners;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const std::string n = withoutCommentsOrSpacing(list[k]->text);
            if (!n.empty() && n != stubNormal) same[n].push_back(k);
            for (const Print& p : winnow(tokens(list[k]->text)))
                if (!stubPrints.count(p.hash)) prints[k].push_back(p);
            std::set<std::uint64_t> seen;
            for (const Print& p : prints[k])
                if (seen.insert(p.hash).second) owners[p.hash].push_back(k);
        }
        std::set<std::pair<std::size_t, std::size_t>> identical;
        for (const auto& [text, who] : same)
            for (std::size_t i = 0; i < who.size(); ++i)
                for (std::size_t j = i + 1; j < who.size(); ++j) identical.insert({who[i], who[j]});
        // At least 4 owners, so that a small class (or a test) still sees a copy shared by three.
        const std::size_t common = std::max<std::size_t>(4, std::size_t(std::ceil(kCommonShare * double(list.size()))));
        std::map<std::pair<std::size_t, std::size_t>, std::size_t> shared;
        for (const auto& [hash, who] : owners) {
            if (who.size() > common) continue;
            for (std::size_t i = 0; i < who.size(); ++i)
                for (std::size_t j = i + 1; j < who.size(); ++j) ++shared[{who[i], who[j]}];
        }
        auto distinct = [&](std::size_t k) {
            std::set<std::uint64_t> s;
            for (const Print& p : prints[k]) s.insert(p.hash);
            return s.size();
        };
        std::set<std::pair<std::size_t, std::size_t>> chosen = identical;
        std::map<std::pair<std::size_t, std::size_t>, double> score;
        for (const auto& [pair, n] : shared) {
            const std::size_t smaller = std::min(distinct(pair.first), distinct(pair.second));
            const double s = smaller ? double(n) / double(smaller) : 0.0;
            score[pair] = s;
            if (n >= kMinShared && s >= kMinSimilarity) chosen.insert(pair);
        }
        for (const auto& pair : chosen) {
            SimilarPair out;
            out.exercise = exercise;
            out.a = list[pair.first]->student;
            out.b = list[pair.second]->student;
            out.identical = identical.count(pair) > 0;
            out.similarity = out.identical ? 1.0 : std::round(score[pair] * 1000.0) / 1000.0;
            // Shared lines: the lines of A and B with the same trimmed text that are not the stub's.
            std::set<std::string> stubLines;
            for (const SimilarityFile& s : stubs)
                if (s.exercise == exercise)
                    for (const std::string& l : linesOf(s.text)) stubLines.insert(trim(l));
            const std::vector<std::string> la = linesOf(list[pair.first]->text), lb = linesOf(list[pair.second]->text);
            std::multimap<std::string, int> inB;
            for (std::size_t k = 0; k < lb.size(); ++k) inB.insert({trim(lb[k]), int(k) + 1});
            for (std::size_t k = 0; k < la.size() && out.lines.size() < 40; ++k) {
                const std::string t = trim(la[k]);
                if (t.size() < 4 || stubLines.count(t) || t.rfind("//", 0) == 0) continue;
                auto it = inB.find(t);
                if (it == inB.end()) continue;
                out.lines.push_back({int(k) + 1, it->second, t});
                inB.erase(it);
            }
            pairs.push_back(out);
        }
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const SimilarPair& x, const SimilarPair& y) {
        if (x.exercise != y.exercise) return x.exercise < y.exercise;
        if (x.identical != y.identical) return x.identical;
        return x.similarity > y.similarity;
    });
    return pairs;
}

nlohmann::json toJson(const std::vector<SimilarPair>& pairs) {
    nlohmann::json out = nlohmann::json::array();
    for (const SimilarPair& p : pairs) {
        nlohmann::json lines = nlohmann::json::array();
        for (const SharedLine& l : p.lines) lines.push_back({{"line_a", l.lineA}, {"line_b", l.lineB}, {"text", l.text}});
        out.push_back({{"exercise", p.exercise},
                       {"a", p.a},
                       {"b", p.b},
                       {"kind", p.identical ? "identical" : "similar"},
                       {"similarity", p.similarity},
                       {"shared_lines", lines}});
    }
    return out;
}

}  // namespace rl
