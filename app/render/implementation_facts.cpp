#include "render/implementation_facts.h"

#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/paths.h"

#include <cctype>
#include <string_view>

namespace rl {

namespace {

constexpr std::uintmax_t kLargestExercise = 1 << 20;  // a larger file is read by the compiler, not here

// GLSL source of a scan: comments dropped (// to the end of the line, /* */).
std::string withoutComments(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n') ++i;
            out += '\n';
        } else if (text.compare(i, 2, "/*") == 0) {
            std::size_t end = text.find("*/", i + 2);
            i = end == std::string_view::npos ? text.size() : end + 1;
            out += ' ';
        } else {
            out += text[i];
        }
    }
    return out;
}

bool namesIdentifier(const std::string& code, const std::string& name) {
    auto isWord = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
        bool before = at > 0 && isWord(code[at - 1]);
        bool after = at + name.size() < code.size() && isWord(code[at + name.size()]);
        if (!before && !after) return true;
    }
    return false;
}

bool finished(const Implementation& impl) {
    for (const ExerciseInfo& exercise : allExercises()) {
        // An optional exercise never holds the specialisations back: no
        // framework code tests its functions for NOT_STARTED, and while it
        // is not ready its neutral values are compiled in (shader/readiness.h).
        if (exercise.optional) continue;
        std::filesystem::path file = impl.fileFor(exercise.file());
        if (isUnchangedStub(file, exercise)) return false;
        try {
            if (namesIdentifier(withoutComments(readRegularFile(file, kLargestExercise)), "NOT_STARTED")) return false;
        } catch (const Error&) {
            return false;  // unreadable: the compiler says why
        }
    }
    return true;
}

// Whether two implementations have the same text for an exercise file (white
// space aside, as isUnchangedStub() compares).
bool sameExercise(const Implementation& a, const Implementation& b, const std::string& file) {
    try {
        return normalisedGlsl(readRegularFile(a.fileFor(file), kLargestExercise)) ==
               normalisedGlsl(readRegularFile(b.fileFor(file), kLargestExercise));
    } catch (const Error&) {
        return false;
    }
}

}  // namespace

ImplementationFacts implementationFacts(const Implementation& impl) {
    ImplementationFacts facts;
    facts.exercisesFinished = finished(impl);
    // traceRay's unit: an exercise of the course, or framework code (always started).
    const ExerciseInfo* reflections = exerciseOfFunction("traceRay");
    facts.traceStarted = !reflections || !reflections->inCourse ||
                         !isUnchangedStub(impl.fileFor(reflections->file()), *reflections);
    const Implementation course{solutionsDir(), {}};
    for (const ExerciseInfo& exercise : allExercises())
        if (sameExercise(impl, course, exercise.file())) facts.courseFiles.insert(exercise.file());
    // A unit the manifest leaves out is the course's own code in every implementation.
    for (const ExerciseInfo& unit : frameworkUnits()) facts.courseFiles.insert(unit.file());
    return facts;
}

}  // namespace rl
