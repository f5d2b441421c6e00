// The course: its exercises in teaching order, and for every function an
// exercise implements what the framework needs to know about it: its
// declaration, the functions it builds on, the framework's neutral value while
// it is not ready (shader/readiness.h compiles that in place of an unfinished
// function, so the physics GLSL never asks whether an exercise is started) and
// how the checker's probe program calls it.
//
// Each exercise is one unit, a folder of course/ (course/README.md): its
// unit.json is compiled in by the build (cmake/course.cmake) and read here;
// course/manifest.txt gives the order and the selection. A unit that the
// manifest does not list is no exercise: its solution.glsl is then part of the
// framework (frameworkUnits()).
//
// This is data, the layer below shader/ and render/: the registry reads no
// file and knows no OpenGL.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

// One function an exercise implements, declared for the framework from its unit.json.
struct ExerciseFunction {
    std::string name;       // "D_GGX"
    std::string signature;  // "float D_GGX(vec3 n, vec3 h, float alpha)": declared for the framework
    // The probe program's call (shaders/probe.glsl, evaluateProbe): GLSL
    // statements over the inputs a..e, the material m, the hit `hit`, that
    // write the result into r.
    std::string probeCall;
    // The body the framework compiles in place of the function while it is
    // not ready, with the declaration's parameter names: a value that shows
    // "not there yet" (no light, no shadow, first hit only, ...), never the
    // answer.
    std::string neutralBody;
    // The functions (of any exercise) it builds on: it is used only once each
    // of them is ready too, so a finished 08 over an unfinished 05 gives
    // Lambert alone, not a wrong highlight.
    std::vector<std::string> needs;
    // Functions of other units the framework calls on this one's behalf
    // ("framework_calls"): the intersection and the shading behind a bounce.
    // The checker's hint names their units when they do not pass yet.
    std::vector<std::string> frameworkCalls;
    // A function without which there is no geometry to see (the camera ray,
    // the intersection): the stripes then cover every pixel, not a frame.
    bool geometry = false;
};

// A numerical strategy `raylab bench --sweeps strategies` times: one of the
// unit's mutants in place of its solution ("bench_strategies" in unit.json).
struct BenchStrategy {
    std::string name;    // "naive-D": the bench row is "strategy:naive-D"
    std::string mutant;  // "mutants/textbook-denominator.glsl", relative to the unit's folder
};

struct ExerciseInfo {
    int number;          // the two digits of its id: 5 for 05-ggx
    std::string id;      // "05-ggx": its unit folder course/05-ggx/, its file in exercises/ and solutions/
    std::string title;   // "the GGX normal distribution D"
    std::vector<ExerciseFunction> functions;  // in the order the unit lists them
    int weight = 10;     // its points in the default rubric (grading/default-rubric.json may override)
    // A further light term the unit adds at every hit (the framework's
    // extension point, lighting.glsl shadeHit): a GLSL expression over
    // `hit`, `v` and the material `m`, giving linear radiance; empty for none.
    std::string light;
    bool inCourse = true;  // listed in course/manifest.txt
    // Listed as "NN-name optional": a bonus exercise, checked and graded like
    // the others, weight 0 in the default rubric, not counted in "N of N
    // exercises pass" and never holding back the picture's specialisations
    // or stripes (docs/decisions.md, "Optional exercises").
    bool optional = false;
    // "shows_with" in unit.json: a define without which the unit's functions
    // add nothing to the picture (RL_ENVIRONMENT); while the unit is
    // unfinished, only programs with it show the stripes. Empty: every program.
    std::string showsWith;
    std::vector<BenchStrategy> benchStrategies;  // "bench_strategies"
    std::string file() const { return id + ".glsl"; }
    std::string unitDir() const { return "course/" + id; }  // relative to the repository's root
    std::string handout() const { return unitDir() + "/handout.md"; }
    std::string stubFile() const { return unitDir() + "/stub.glsl"; }
    std::string solutionFile() const { return unitDir() + "/solution.glsl"; }
};

// The course's exercises, in the manifest's order.
const std::vector<ExerciseInfo>& allExercises();
// The course's exercises that are not optional: what "N of N exercises pass" counts.
std::vector<ExerciseInfo> requiredExercises();
// The units the manifest does not list: their solutions are framework code.
const std::vector<ExerciseInfo>& frameworkUnits();
// By number (1..10) or id ("05-ggx"); throws rl::Error listing the valid ones.
const ExerciseInfo& findExercise(const std::string& numberOrId);
// The id by which the probe program (u_probeFunction) selects `function`: its
// place among every unit's functions, or -1 for a name no unit implements.
int probeFunctionId(const std::string& function);

// The unit (course exercise or framework unit) that implements `function`, or nullptr.
const ExerciseInfo* exerciseOfFunction(const std::string& function);

// True when `file` is the stub shipped for this exercise (what `raylab check`
// reports as NOT STARTED): the same text once white space (CR included) and a
// UTF-8 byte-order mark are dropped. "Shipped" is the unit's stub.glsl as it
// was when the program was built (compiled in, see cmake/course.cmake), never
// exercises/, which is the student's own work.
bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise);

// The comparison form of GLSL text: no white space, no BOM.
std::string normalisedGlsl(const std::string& text);

// The shipped stub `fileName` ("05-ggx.glsl") as compiled in, or nullptr.
const std::string* shippedStub(const std::string& fileName);

}  // namespace rl
