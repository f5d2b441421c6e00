#include "grading/class_similarity.h"

#include "grading/atomic_file.h"
#include "core/paths.h"
#include "course/exercise_registry.h"
#include "grading/similarity.h"

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace rl {

nlohmann::json classSimilarity(const fs::path& out, const Rubric& rubric, const std::vector<StudentGrade>& grades) {
    std::vector<SimilarityFile> files, base;
    std::error_code ec;
    // A graded copy is at most the staging limit (300 KiB per file); read no more.
    constexpr std::uintmax_t kMaxBytes = 1u << 20;
    auto readSmall = [&](const fs::path& file, std::string& text) {
        if (!fs::is_regular_file(fs::symlink_status(file, ec)) || fs::file_size(file, ec) > kMaxBytes) return false;
        try {
            text = readWholeFile(file);
            return true;
        } catch (const std::exception&) {
            return false;
        }
    };
    for (const RubricExercise& r : rubric.exercises) {
        const ExerciseInfo& info = findExercise(r.id);
        std::string text;
        if (readSmall(exercisesDir() / info.file(), text)) base.push_back({"", r.id, text});
        if (hasSolutions() && readSmall(solutionsDir() / info.file(), text)) base.push_back({"", r.id, text});
        for (const StudentGrade& g : grades) {
            const ExerciseGrade* x = g.find(r.id);
            if (!x || x->refused) continue;
            if (readSmall(studentDir(out, g.id) / "submission" / info.file(), text)) files.push_back({g.id, r.id, text});
        }
    }
    return toJson(findSimilarSubmissions(files, base));
}

}  // namespace rl
