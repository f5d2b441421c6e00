// The course: its exercises in teaching order, and for every function an
// exercise implements what the framework needs to know about it: the
// exercises it builds on, and the framework's neutral value while it is not
// ready (shader/readiness.h compiles that in place of an unfinished function,
// so the physics GLSL never asks whether an exercise is started).
//
// This is data, the layer below shader/ and render/: the registry reads no
// file and knows no OpenGL.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

// One function an exercise implements, declared in shaders/declarations.glsl.
struct ExerciseFunction {
    std::string name;  // "D_GGX"
    // The body the framework compiles in place of the function while it is
    // not ready, with the declaration's parameter names: a value that shows
    // "not there yet" (no light, no shadow, first hit only, ...), never the
    // answer.
    std::string neutralBody;
    // The functions (of any exercise) it builds on: it is used only once each
    // of them is ready too, so a finished 08 over an unfinished 05 gives
    // Lambert alone, not a wrong highlight.
    std::vector<std::string> needs;
    // A function without which there is no geometry to see (the camera ray,
    // the intersection): the stripes then cover every pixel, not a frame.
    bool geometry = false;
};

struct ExerciseInfo {
    int number;          // 1..10, its place in the course
    std::string id;      // "05-ggx": file stem in exercises/ and solutions/
    std::string title;   // "the GGX normal distribution D"
    std::vector<ExerciseFunction> functions;  // in the order of declarations.glsl
    std::string file() const { return id + ".glsl"; }
    std::string handout() const { return "docs/exercises/" + id + ".md"; }
};

const std::vector<ExerciseInfo>& allExercises();
// By number (1..10) or id ("05-ggx"); throws rl::Error listing the valid ones.
const ExerciseInfo& findExercise(const std::string& numberOrId);
// The exercise that implements `function`, or nullptr.
const ExerciseInfo* exerciseOfFunction(const std::string& function);

// True when `file` is the stub shipped for this exercise (what `raylab check`
// reports as NOT STARTED): the same text once white space (CR included) and a
// UTF-8 byte-order mark are dropped. "Shipped" is exercises/ as it was when the
// program was built (compiled in, see cmake/shipped_stubs.cmake), never the
// live folder, which is the student's own work.
bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise);

// The comparison form of GLSL text: no white space, no BOM.
std::string normalisedGlsl(const std::string& text);

// The shipped stub `fileName` ("05-ggx.glsl") as compiled in, or nullptr.
// Defined in the generated shipped_stubs.cpp.
const std::string* shippedStub(const std::string& fileName);

}  // namespace rl
