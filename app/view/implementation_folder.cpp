#include "view/implementation_folder.h"

#include "course/exercise_registry.h"
#include "course/fallback_files.h"
#include "core/error.h"
#include "core/paths.h"

namespace fs = std::filesystem;

namespace rl {

namespace {

// "05-ggx--missing-pi.glsl" and "05-ggx.glsl" -> the exercise 05-ggx.
Implementation fromSingleFile(const fs::path& file, const std::string& option) {
    const std::string stem = file.stem().string();
    const std::string id = stem.substr(0, stem.find("--"));
    for (const ExerciseInfo& e : allExercises())
        if (e.id == id && file.extension() == ".glsl")
            return Implementation{fallbackImplementationDir(), {{e.file(), file}}};
    const std::string example = allExercises().empty() ? std::string("NN-name") : allExercises().front().id;
    throw Error(option + ": " + file.string() + " is not named after an exercise (expected e.g. " + example +
                ".glsl or " + example + "--what-is-wrong.glsl)");
}

}  // namespace

Implementation implementationFrom(const fs::path& path, const std::string& option) {
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) return fromSingleFile(path, option);
    if (!fs::is_directory(path, ec)) throw Error(option + ": " + path.string() + " does not exist");
    const fs::path& dir = path;
    Implementation impl{dir, {}};
    int present = 0;
    for (const ExerciseInfo& e : allExercises())
        if (fs::is_regular_file(dir / e.file(), ec)) ++present;
    if (present == int(allExercises().size())) return impl;
    if (present == 0)
        throw Error(option + ": " + dir.string() + " has none of the exercise files (" + allExercises().front().file() +
                    " ... " + allExercises().back().file() + ")");
    impl.dir = fallbackImplementationDir();
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
    auto dirName = [&](const fs::path& dir) {
        return !hasSolutions() && dir == shippedStubFolder() ? std::string("shipped stubs") : shortName(dir);
    };
    if (impl.overrides.empty()) return dirName(impl.dir);
    const fs::path first = impl.overrides.begin()->second.lexically_normal();
    const fs::path folder = first.parent_path();
    // One file: name the file (a mutant's name says what is wrong); several: the folder.
    std::string shown =
        impl.overrides.size() == 1
            ? shortName(folder) + "/" + first.filename().string()
            : (folder.has_parent_path() ? shortName(folder.parent_path()) + "/" : "") + shortName(folder);
    return shown + " (+ " + dirName(impl.dir) + ")";
}

}  // namespace rl
