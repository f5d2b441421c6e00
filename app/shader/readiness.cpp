#include "shader/readiness.h"

#include "core/paths.h"
#include "course/exercise_registry.h"
#include "shader/driver_log.h"
#include "shader/glsl_scan.h"
#include "shader/source_assembler.h"

#include <map>

namespace rl {

bool Readiness::allReady() const {
    for (const FunctionReadiness& f : functions)
        if (!f.ready) return false;
    return true;
}

bool Readiness::isReady(const std::string& function) const {
    for (const FunctionReadiness& f : functions)
        if (f.name == function) return f.ready;
    return false;
}

int probeExerciseOf(const ShaderDefines& defines) {
    auto it = defines.find("RL_PROBE_EXERCISE");
    if (it == defines.end()) return 0;
    try {
        return std::stoi(it->second);
    } catch (const std::exception&) {
        return 0;
    }
}

namespace {

// Per function name: whether the file's definition of it names NOT_STARTED.
// Empty when the file cannot be read (it then counts as started).
std::map<std::string, bool> stubbedFunctions(const std::filesystem::path& file) {
    std::map<std::string, bool> stubbed;
    std::string text;
    try {
        text = readSourceFile(file);
    } catch (const std::exception&) {
        return stubbed;
    }
    for (const GlslFunction& f : scanGlsl(text).functions)
        if (f.hasBody) stubbed[f.name] = stubbed[f.name] || f.bodyNamesNotStarted;
    return stubbed;
}

}  // namespace

Readiness readinessOf(const Implementation& impl, int probeExercise) {
    Readiness out;
    for (const ExerciseInfo& e : allExercises()) {
        const std::filesystem::path file = impl.fileFor(e.file());
        const bool probed = e.number == probeExercise;
        const bool stub = !probed && isUnchangedStub(file, e);
        const std::map<std::string, bool> stubbed = probed || stub ? std::map<std::string, bool>{} : stubbedFunctions(file);
        for (const ExerciseFunction& f : e.functions) {
            auto it = stubbed.find(f.name);
            bool started = probed || (!stub && !(it != stubbed.end() && it->second));
            out.functions.push_back({f.name, e.number, started, started});
        }
    }
    for (const ExerciseInfo& e : frameworkUnits())  // framework code: always ready
        for (const ExerciseFunction& f : e.functions) out.functions.push_back({f.name, e.number, true, true});
    // ready = started and every need ready. The registry lists needs of
    // earlier or the same exercises, but the fixed point below does not rely
    // on it: at most one pass per function, no recursion.
    for (std::size_t pass = 0; pass <= out.functions.size(); ++pass) {
        bool changed = false;
        for (FunctionReadiness& f : out.functions) {
            if (!f.ready || f.exercise == probeExercise) continue;
            const ExerciseInfo* e = exerciseOfFunction(f.name);
            for (const ExerciseFunction& spec : e->functions) {
                if (spec.name != f.name) continue;
                for (const std::string& need : spec.needs)
                    if (!out.isReady(need)) {
                        f.ready = false;
                        changed = true;
                    }
            }
        }
        if (!changed) break;
    }
    return out;
}

std::string exerciseDeclarationsGlsl() {
    std::string text =
        "// exercise_declarations.glsl, written by the host (app/shader/readiness.cpp) from the\n"
        "// course's units (course/*/unit.json): every function an exercise implements.\n";
    for (const auto* units : {&allExercises(), &frameworkUnits()})
        for (const ExerciseInfo& e : *units) {
            text += "// " + e.id + "\n";
            for (const ExerciseFunction& f : e.functions) text += f.signature + ";\n";
        }
    return text;
}

std::string exercisesGlsl(const Readiness& readiness) {
    std::string text =
        "// exercises.glsl, written by the host (app/shader/readiness.cpp) from the course's units\n"
        "// (course/manifest.txt, course/*/unit.json) and the files of this implementation: the\n"
        "// exercise files in the course's order; a function that is not ready yet is renamed away\n"
        "// and the framework's neutral value compiled in its place. Then the units that are no\n"
        "// exercise of this course, whose solutions are framework code.\n";
    bool unfinished = false;
    for (const ExerciseInfo& e : allExercises()) {
        std::vector<const ExerciseFunction*> waiting;
        for (const ExerciseFunction& f : e.functions)
            if (!readiness.isReady(f.name)) waiting.push_back(&f);
        for (const ExerciseFunction* f : waiting) text += "#define " + f->name + " " + kUnfinishedPrefix + f->name + "\n";
        text += "#include \"exercise/" + e.file() + "\"\n";
        for (const ExerciseFunction* f : waiting) {
            text += "#undef " + f->name + "\n";
            text += f->signature + " { " + f->neutralBody + " }\n";
        }
        // The stripes: everywhere, or only where the unit's functions show ("shows_with").
        if (!waiting.empty() && e.showsWith.empty()) unfinished = true;
        if (!waiting.empty() && !e.showsWith.empty())
            text += "#if defined(" + e.showsWith + ") && !defined(RL_UNFINISHED)\n#define RL_UNFINISHED\n#endif\n";
        for (const ExerciseFunction& f : e.functions)
            if (readiness.isReady(f.name)) text += "#define RL_READY_" + f.name + "\n";
    }
    for (const ExerciseInfo& e : frameworkUnits()) {
        text += "#include \"unit/" + e.id + "/solution.glsl\"\n";
        for (const ExerciseFunction& f : e.functions) text += "#define RL_READY_" + f.name + "\n";
    }
    // The extension point (lighting.glsl, shadeHit): the further light terms
    // of the units whose functions are all ready.
    std::string terms;
    for (const auto* units : {&allExercises(), &frameworkUnits()})
        for (const ExerciseInfo& e : *units) {
            if (e.light.empty()) continue;
            bool ready = true;
            for (const ExerciseFunction& f : e.functions) ready = ready && (!e.inCourse || readiness.isReady(f.name));
            if (ready) terms += "    radiance += " + e.light + ";  // " + e.id + "\n";
        }
    if (!terms.empty())
        text += "#define RL_UNIT_LIGHT\nvec3 unitLight(Hit hit, vec3 v, Material m) {\n    vec3 radiance = vec3(0.0);\n" +
                terms + "    return radiance;\n}\n";
    if (unfinished) text += "#define RL_UNFINISHED\n";
    return text;
}

std::string probeDispatchGlsl(int probeExercise) {
    std::string text =
        "// probe_dispatch.glsl, written by the host (app/shader/readiness.cpp) from the course's\n"
        "// units: the call of each function the probe program can evaluate (course/*/unit.json,\n"
        "// \"probe\"), selected by u_probeFunction.\n";
    for (const auto* units : {&allExercises(), &frameworkUnits()})
        for (const ExerciseInfo& e : *units) {
            if (probeExercise != 0 && e.number != probeExercise) continue;
            for (const ExerciseFunction& f : e.functions)
                text += "if (f == " + std::to_string(probeFunctionId(f.name)) + ") {  // " + f.name + "\n" + f.probeCall +
                        (f.probeCall.empty() || f.probeCall.back() == '\n' ? "" : "\n") + "}\n";
        }
    return text;
}

}  // namespace rl
