// The picture program for the course's own exercise files (issue #25): when
// every exercise file is the course's solution (render/implementation_facts.h
// knows), the host knows exactly what code the student-facing API would run,
// so the generator, not the exercise API, decides the code. It writes one
// fragment shader per scene with every number a constant, from the same
// techniques as the bench's expert yardstick (bench/expert.h: the camera
// folded into one expression, no ray offsets, shadow tests from the light's
// side, per-(light, receiver) occluder masks, ...), plus culling that a
// hand-written per-scene shader does not do (CourseProgramOptions): the sky
// tiles drawn with the same generator's program with no sphere, the tables
// as uniforms, branch-free shadow tests. Each only removes work that cannot
// change a pixel: the picture is the same.
// A student's own file is never replaced: courseProgramApplies() is false
// and the picture program of shaders/ runs that file's code.
#pragma once

#include "core/scene.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "shader/program.h"

#include <string>

namespace rl {

// Each layer beyond the expert's techniques, kept on only where `raylab bench`
// showed it pays at equal error (640x480, llvmpipe, 2 cores, CPU clock; the
// figures are in docs/decisions.md, "The course's generated picture program").
// On llvmpipe an `if` only masks the lanes of a pixel group: its body runs
// for the whole group, so culling by `if` saves nothing and costs its test;
// what skips work is a scissored draw (the sky tiles) or a loop that ends.
struct CourseProgramOptions {
    bool skyTiles = true;           // a program with no sphere for the sky tiles (render/sky_tiles.h): 1.2-2.6x
    bool selectTables = true;       // tables of at most 8 values as functions of selects (scene_facts.h): 1.1-1.2x
    bool uniformTables = false;     // per-id tables as initialised uniforms: as fast as const arrays at best, and in some processes 1.3-1.5x slower (random-30: 40-47 ms of CPU against 32)
    bool branchFreeShadows = true;  // shadow tests without `if`, the receiver by its id: equal, within noise
    bool screenRects = false;       // camera rays: per-sphere pixel bounds around the test: costs 0-8%
    bool bounceGroups = false;      // bounce rays: bounding spheres of clusters around the tests: costs 0-8%
    bool shadowLists = false;       // per-(light, receiver) candidate lists walked by a loop: 1.6-2.5x slower (gathers)
    // Per-tile programs (app/render/course_program.cpp): 16x16-pixel screen
    // tiles grouped by the spheres their camera rays may hit and the spheres
    // that may shadow those hits (the hits' visible patches, bounded on the
    // host in double), each group drawn (scissored) by a program whose first
    // hit tests only those; the bounces as before. A cost model picks how many
    // programs: draw time saved against compiles over `frames` frames and a
    // per-program cost per frame. Off everywhere: once the driver's heap was
    // kept between frames (gl/context.h) the one program with its sky tiles
    // was faster on every scene measured (random-30 33 ms of CPU a frame
    // against 38 ms in 13 programs; docs/decisions.md, "Per-tile programs").
    bool tilePrograms = false;
    int frames = 1;     // frames the program will draw: one for `raylab render`
    int tileSize = 16;  // pixels a side
    bool tileCostModel = true;  // false: one program per group (up to 12) whatever it costs (tests)
    // The tiles' occluders as uniform lists walked by loops with uniform
    // bounds, in one program: lecture 0.67-0.8x against 1.38x (gathers), off.
    bool tileLists = false;
};

// Whether `raylab render` may draw `scene` with the generated program: the
// reference model and every exercise file the course's own.
bool courseProgramApplies(const Scene& scene, const ImplementationFacts& facts);

// The fragment shader's text for `scene` at scene.render's size (GLSL 3.30).
std::string courseProgramSource(const Scene& scene, const CourseProgramOptions& options = {});

// Compiles it with fullscreen.vert (throws ShaderError / rl::Error).
ShaderProgram buildCourseProgram(const Scene& scene, const CourseProgramOptions& options = {});

// The program and, for the sky tiles, the same generator's program with no
// sphere: what `raylab render` and the bench's `specialised` row draw with.
PictureProgram buildCoursePicture(const Scene& scene, const CourseProgramOptions& options = {});

}  // namespace rl
