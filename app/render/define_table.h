// The specialisation policy in one place: every RL_ define the host compiles
// into the ray tracer, in one table (define_table.cpp), and the one function
// that every program's defines come from, definesFor(scene, facts, purpose).
// Each row says what its value depends on, for which purposes it applies,
// which other defines it requires and excludes, why it pays, and which
// function computes it (render/define_values.h). No caller adds, removes or
// filters another's defines: the sky tiles' program is the table's InSky
// column applied to the picture's, and the bench's layers sweep takes out,
// one at a time, the rows its BenchLayer column marks (an experiment, not a
// program anything else draws with). A unit test (tests/unit/test_define_table.cpp)
// keeps the table and the RL_ names of shaders/ in step both ways.
//
// Two scenes with equal defines share one compiled program; the live view
// recompiles only when they differ (docs/performance.md measures each row).
#pragma once

#include "core/scene.h"
#include "render/implementation_facts.h"
#include "shader/shader_library.h"

#include <optional>
#include <string>
#include <vector>

namespace rl {

// What a program is built for.
enum class Purpose {
    Picture,         // one picture from one camera: `raylab render` (final, bounce K), the bench's
                     // "specialised" row, the accuracy tests
    EveryView,       // the scene's structure and values, every view compiled in: `raylab render --view d`,
                     // the bench's "specialised-full" row, the browser page
    LiveView,        // the live view's picture program while a slider moves (`raylab view`, final and
                     // bounce views): nothing a slider or the camera changes
    LiveStill,       // the live view's picture program otherwise: the scene's values too, not the camera
    Probe,           // the checker's ray tracer (`raylab check`): one program for every check scene
    GenericPicture,  // the bench's "generic-picture" row: the generic program without the term views
    Generic,         // the model only: `raylab render --generic`, the live view's term views, `raylab record`
    PixelDebug,      // the pixel debugger's recorder (`raylab render --ask`, the live view's click): the
                     // generic program without the environment's occlusion, which the reference's
                     // breakdown it is compared with does not have (render/pixel_debugger.h)
};
inline constexpr int kPurposeCount = 8;
const char* purposeName(Purpose purpose);  // "picture", "every-view", "live-view", "live-still", "probe", ...

// What a row's value depends on (a bit set). The live view compiles only rows
// of Model, Structure, Geometry and Files (and SampleGrid's spp, a program per
// count), so that no slider and no camera move recompiles.
enum Depends : unsigned {
    kModel = 1u << 0,      // scene.model
    kStructure = 1u << 1,  // counts, the bounce limit
    kGeometry = 1u << 2,   // sphere centres and radii (the live view's panel does not edit them)
    kValues = 1u << 3,     // materials, lights, samples per pixel (the panel edits them)
    kCamera = 1u << 4,     // the camera's position
    kFiles = 1u << 5,      // the implementation's files (ImplementationFacts)
    kPurpose = 1u << 6,    // the purpose alone
};

constexpr unsigned purposeBit(Purpose p) { return 1u << unsigned(p); }

// Whether the bench's layers sweep (`raylab bench --sweeps layers`) measures
// the picture program without this row ("without:NAME") and, where the row
// is a threshold's choice, with it where the threshold left it out
// ("with:NAME", when benchWith(scene) allows it).
enum class BenchLayer { None, Without };

struct DefineInput {
    const Scene& scene;
    const ImplementationFacts& facts;
    Purpose purpose;
    const ShaderDefines& sofar;  // the rows above this one, as decided
};

struct DefineRow {
    // As compiled; a function-like macro with its parameter: "RL_FOR_EACH_LIGHT(X)". A string, so
    // that rows made from a list (one per exercise, say) are rows like the others.
    std::string name;
    unsigned dependsOn;               // Depends bits
    unsigned purposes;                // purposeBit()s it applies to
    std::vector<std::string> needs;     // defines above it that must be present
    std::vector<std::string> excludes;  // defines above it that must be absent
    const char* reason;               // one line: why it pays, or what it selects
    std::optional<std::string> (*value)(const DefineInput&);  // nullopt: not defined
    bool glsl = true;                 // false: read by the host only (RL_SKY_TILES)
    BenchLayer layer = BenchLayer::None;
    bool (*benchWith)(const Scene&) = nullptr;  // the layers sweep's "with:" row, where the scene allows it
};

// Every row, in the order definesFor() decides them (a row's needs and
// excludes name rows above it).
const std::vector<DefineRow>& defineTable();

// The name as the shaders spell it: "RL_FOR_EACH_LIGHT(X)" -> "RL_FOR_EACH_LIGHT".
std::string glslName(const DefineRow& row);

// RL_ names of shaders/ that are not specialisation defines: the probe's
// exercise (checker.cpp), the shaders' own macros and constants.
const std::vector<const char*>& nonSpecialisationNames();

// The defines of a program for `purpose` of `scene` with the implementation
// whose facts are `facts`. Pure: reads no file. A program that trusts
// traceRay() is built only once exercise 09 is started: until then a Picture
// is drawn by the EveryView program and the LiveView by the Generic one.
ShaderDefines definesFor(const Scene& scene, const ImplementationFacts& facts, Purpose purpose);

// The generic program's defines for `model` (definesFor(..., Generic) of a
// scene with that model): what selects the model variants.
ShaderDefines modelDefines(const ShadingModel& model);

// Not a GLSL define: set in a Picture program when the screen tiles that no
// camera ray can hit a sphere in may be drawn by the program of
// skyProgramDefines() (render/sky_tiles.h).
inline constexpr const char* kSkyTilesDefine = "RL_SKY_TILES";

// The program for the sky tiles of a picture program: the picture's defines
// and RL_SKY, with which closestHit() checks that the ray misses every sphere
// (marking the pixel where it does not) and shades nothing (main.frag,
// intersect_scene.glsl). None unless `picture` has kSkyTilesDefine and
// RL_PICTURE_ONLY.
std::optional<ShaderDefines> skyProgramDefines(const ShaderDefines& picture);

// The rows whose program checks an assumption pixel by pixel and marks the
// pixels where it does not hold (main.frag): RL_SHADOW_STEPS, and RL_SKY in a
// sky program.
bool marksPixels(const ShaderDefines& defines);

// The program that draws a picture program's marked pixels again: its
// defines without the assumptions (marksPixels() false for it).
ShaderDefines withoutAssumptions(const ShaderDefines& defines);

}  // namespace rl
