#include "view/implementation_folder.h"

#include "checks/exercise_registry.h"
#include "core/error.h"
#include "core/paths.h"

namespace fs = std::filesystem;

namespace rl {

Implementation implementationFromFolder(const fs::path& dir, const std::string& option) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw Error(option + ": " + dir.string() + " is not a directory");
    Implementation impl{dir, {}};
    int present = 0;
    for (const ExerciseInfo& e : allExercises())
        if (fs::is_regular_file(dir / e.file(), ec)) ++present;
    if (present == int(allExercises().size())) return impl;
    if (present == 0)
        throw Error(option + ": " + dir.string() + " has none of the exercise files (" + allExercises().front().file() +
                    " ... " + allExercises().back().file() + ")");
    impl.dir = solutionsDir();
    for (const ExerciseInfo& e : allExercises())
        if (fs::is_regular_file(dir / e.file(), ec)) impl.overrides[e.file()] = dir / e.file();
    return impl;
}

std::string implementationLabel(const Implementation& impl) {
    auto shortName = [](const fs::path& p) {
        fs::path clean = p.lexically_normal();
        if (clean.filename().empty()) clean = clean.parent_path();  // "exercises/" -> "exercises"
        return clean.filename().string();
    };
    if (impl.overrides.empty()) return shortName(impl.dir);
    fs::path folder = impl.overrides.begin()->second.parent_path().lexically_normal();
    std::string parent = folder.has_parent_path() ? shortName(folder.parent_path()) + "/" : "";
    return parent + shortName(folder) + " (+ " + shortName(impl.dir) + ")";
}

}  // namespace rl
