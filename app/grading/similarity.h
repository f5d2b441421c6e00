// Similar submissions: pairs of students whose exercise files are the same
// once whitespace and comments are normalised away ("identical"), or share
// most of their code ("similar"), found by winnowing (Schleimer, Wilkerson
// and Aiken 2003, as Dolos and MOSS do) over GLSL tokens. The stub's own code
// and code that many students share (the few lines every finished exercise
// has) are left out, so that what is left is what a student wrote.
// It is information for the instructor, listed in the report with the
// shared lines side by side; it never changes a grade. See docs/decisions.md
// for why this is not Dolos.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rl {

struct SimilarityFile {
    std::string student;   // the student's id
    std::string exercise;  // "05-ggx"
    std::string text;      // the graded file
};

struct SharedLine {
    int lineA = 0, lineB = 0;
    std::string text;  // the line as student A wrote it (trimmed)
};

struct SimilarPair {
    std::string exercise;
    std::string a, b;      // student ids, a < b
    bool identical = false;
    double similarity = 0;  // shared fingerprints / the smaller file's fingerprints (1 when identical)
    std::vector<SharedLine> lines;  // at most 40
};

// `stub`: the exercise's file as shipped, per exercise id (its code is never
// evidence). Pairs sorted by exercise, identical first, then similarity.
std::vector<SimilarPair> findSimilarSubmissions(const std::vector<SimilarityFile>& files,
                                                const std::vector<SimilarityFile>& stubs);

// The text without comments, with every run of white space one space (what "identical" compares).
std::string withoutCommentsOrSpacing(const std::string& text);

nlohmann::json toJson(const std::vector<SimilarPair>& pairs);

}  // namespace rl
