// Similar submissions, the way MOSS and Dolos find them, reported as
// clusters. Per exercise, each file is cut into GLSL tokens with every
// identifier that is not GLSL's own (keywords, types, built-in functions,
// swizzles) replaced by one placeholder, so renaming is seen through; the
// tokens are fingerprinted by winnowing (Schleimer, Wilkerson and Aiken
// 2003) one top-level function (or declaration) at a time, so a file whose
// functions are reordered has the same fingerprints. Base code is never
// evidence: fingerprints of the course's stub and solution, and those that
// more than a set share of the class's files hold (Dolos's
// maxFingerprintPercentage). Students whose files share enough of what is
// left are joined into clusters: ten students with one file are one cluster,
// not 45 pairs. Clusters with the same students over several exercises are
// one entry, and at most `limit` entries are kept, the strongest evidence
// first, so the report is bounded for any class size.
// It is information for the instructor, listed in the report with the
// shared lines side by side; it never changes a grade. docs/decisions.md
// says why this is not Dolos itself.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace rl {

struct SimilarityFile {
    std::string student;   // the student's id ("" for the course's own files)
    std::string exercise;  // "05-ggx"
    std::string text;      // the graded file
};

struct SharedLine {
    int lineA = 0, lineB = 0;
    std::string text;  // the line as student A wrote it (trimmed, at most 160 bytes)
};

struct SimilarPair {
    std::string exercise, a, b;  // a < b; each stands for the students with a file identical to theirs
    std::size_t evidence = 0;    // shared fingerprints outside base code
    double similarity = 0;       // evidence / the smaller file's evidence
};

struct SimilarCluster {
    std::vector<std::string> students;   // sorted; at least 2 (at most kMaxClusterStudents listed)
    std::size_t studentCount = 0;        // all of them
    std::vector<std::string> exercises;  // where they share code, in order
    bool identical = false;              // every file of the cluster the same after comments and white space
    std::size_t evidence = 0;            // shared fingerprints outside base code, summed over the exercises
    double similarity = 0;               // the strongest pair's share of the smaller file's evidence (0..1)
    // The strongest pair of the strongest exercise, with their shared lines (at most 12).
    std::string exercise, a, b;
    std::vector<SharedLine> lines;
    // The pairs of differing files that joined the cluster, the strongest first (at most kMaxClusterPairs).
    std::vector<SimilarPair> pairs;
};

struct SimilarityReport {
    std::vector<SimilarCluster> clusters;  // the strongest evidence first, at most `limit`
    std::size_t clustersFound = 0;         // before the limit
    std::size_t filesCompared = 0;
};

constexpr std::size_t kMaxClusterStudents = 50;
constexpr std::size_t kMaxClusterPairs = 12;

// `base`: the course's stub and solution files (their code is never evidence).
SimilarityReport findSimilarSubmissions(const std::vector<SimilarityFile>& files,
                                        const std::vector<SimilarityFile>& base, std::size_t limit = 200);

// The text without comments, with every run of white space one space (what "identical" compares).
std::string withoutCommentsOrSpacing(const std::string& text);

// The tokens fingerprinting sees: identifiers that are not GLSL's own become "$".
std::string normalisedTokens(const std::string& text);

nlohmann::json toJson(const SimilarityReport& report);

}  // namespace rl
