// The table of every RL_ define (render/define_table.h). One row per define,
// in the order they are decided; the reasons are the short form of the
// comments the shaders carry where each is read, and of docs/performance.md.
#include "render/define_table.h"

#include "course/exercise_registry.h"

#include "render/define_values.h"
#include "render/scene_constants.h"

#include <algorithm>

namespace rl {

namespace {

using Value = std::optional<std::string>;
const Value kOne = std::string("1");
const Value kNone = std::nullopt;

Value when(bool condition) { return condition ? kOne : kNone; }

constexpr unsigned kPicture = purposeBit(Purpose::Picture);
constexpr unsigned kEveryView = purposeBit(Purpose::EveryView);
constexpr unsigned kLive = purposeBit(Purpose::LiveView);
constexpr unsigned kLiveStill = purposeBit(Purpose::LiveStill);
constexpr unsigned kProbe = purposeBit(Purpose::Probe);
constexpr unsigned kGenericPicture = purposeBit(Purpose::GenericPicture);
constexpr unsigned kGeneric = purposeBit(Purpose::Generic);
constexpr unsigned kPixelDebug = purposeBit(Purpose::PixelDebug);
// The model is compiled into every program drawn for a scene; the checker's
// one program serves every check scene, so it has none.
constexpr unsigned kEveryScene = kPicture | kEveryView | kLive | kLiveStill | kGenericPicture | kGeneric | kPixelDebug;
// What a specialised program compiles in.
constexpr unsigned kSpecialised = kPicture | kEveryView | kLive | kLiveStill;
// The picture programs of the live view.
constexpr unsigned kLivePictures = kLive | kLiveStill;
// What compiles the scene's geometry in: the picture programs (the live
// view's panel does not edit it). The program of every view keeps it in
// uniforms, as the browser page's live picture needs.
constexpr unsigned kGeometryConstants = kPicture | kLivePictures;
// What compiles the scene's values in too: a program for one picture, and
// the live view's still picture (its camera stays a uniform).
constexpr unsigned kOnePicture = kPicture | kLiveStill;

int sphereCount(const DefineInput& in) { return int(in.scene.spheres.size()); }

// A data row's macro where there is something to index, each index a
// constant (written out: render/scene_constants.h): a scene without spheres
// (or lights) never calls the accessor, and a loop over them reads the
// uniform block, as in the generic program, where a chain of selects on a
// varying index would cost a test per sphere.
Value spheresOrNone(const DefineInput& in, std::string (*macro)(const Scene&)) {
    return in.scene.spheres.empty() || !writesSpheresOut(in.scene) ? kNone : Value(macro(in.scene));
}
Value lightsOrNone(const DefineInput& in, std::string (*macro)(const Scene&)) {
    return in.scene.lights.empty() || !writesLightsOut(in.scene) ? kNone : Value(macro(in.scene));
}

std::vector<DefineRow> makeTable() {
    std::vector<DefineRow> t;

    // ---- the purpose alone.
    t.push_back({"RL_PIXEL_DEBUG", kPurpose, kPixelDebug, {}, {},
                 "pixel_debug.frag records the exercises' values at one pixel (render/pixel_debugger.h)",
                 [](const DefineInput&) { return kOne; }});

    // ---- the model (docs/model-variants.md): the reference model has none,
    // so every reference scene shares one generic program.
    t.push_back({"RL_MODEL_VARIANTS", kModel, kEveryScene, {}, {},
                 "raytracer.glsl includes model_variants.glsl, only for a model other than the reference",
                 [](const DefineInput& in) { return when(!in.scene.model.isReference()); }});
    t.push_back({"RL_BLINN_PHONG", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {},
                 "the whole BRDF replaced; the other switches are ignored, as in the CPU reference",
                 [](const DefineInput& in) { return when(in.scene.model.blinnPhong); }});
    t.push_back({"RL_D_BECKMANN", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "the Beckmann distribution instead of GGX",
                 [](const DefineInput& in) { return when(in.scene.model.distribution == DistributionModel::Beckmann); }});
    t.push_back({"RL_G_SMITH_SEPARABLE", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "Smith GGX, separable, instead of Schlick-GGX",
                 [](const DefineInput& in) { return when(in.scene.model.geometry == GeometryModel::SmithGGXSeparable); }});
    t.push_back({"RL_G_SMITH_CORRELATED", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "Smith GGX, height-correlated, instead of Schlick-GGX",
                 [](const DefineInput& in) { return when(in.scene.model.geometry == GeometryModel::SmithGGXCorrelated); }});
    t.push_back({"RL_F_DIELECTRIC", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "the exact dielectric Fresnel instead of Schlick's",
                 [](const DefineInput& in) { return when(in.scene.model.fresnel == FresnelModel::Dielectric); }});
    t.push_back({"RL_F_CONDUCTOR", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "the conductor Fresnel with an edge tint instead of Schlick's",
                 [](const DefineInput& in) { return when(in.scene.model.fresnel == FresnelModel::Conductor); }});
    t.push_back({"RL_FD_BURLEY", kModel, kEveryScene, {"RL_MODEL_VARIANTS"}, {"RL_BLINN_PHONG"},
                 "Burley's diffuse instead of Lambert's",
                 [](const DefineInput& in) { return when(in.scene.model.diffuse == DiffuseModel::Burley); }});

    // ---- light from all around (issue 24, shaders/environment.glsl): only a scene with an
    // "environment" compiles it in, so every other picture is the same program as before.
    t.push_back({"RL_ENVIRONMENT", kStructure, kEveryScene, {}, {},
                 "the environment map, its SH9 irradiance and prefiltered specular (environment.glsl), only "
                 "for a scene with an environment",
                 [](const DefineInput& in) { return when(in.scene.environment.has_value()); }});
    // Not in the pixel debugger's program: its double side (reference/pixel_breakdown.h) compares
    // exercise 11's terms and 12's form factors, not the occlusion's framework parts.
    t.push_back({"RL_ENV_OCCLUSION", kStructure, kEveryScene & ~kPixelDebug, {"RL_ENVIRONMENT"}, {},
                 "the spheres' caps taken out of the environment light (environment_occlusion.glsl): the strategy, 2 "
                 "(the caps' own light and the sun), for two spheres or more",
                 [](const DefineInput& in) { return in.scene.spheres.size() > 1 ? Value("2") : kNone; }});

    // ---- the scene's structure (scene.glsl): loops unrolled, every index a constant.
    t.push_back({"RL_SPHERE_COUNT", kStructure, kSpecialised, {}, {},
                 "the sphere loops unrolled with direct loads instead of a per-lane gather per iteration",
                 [](const DefineInput& in) -> Value { return std::to_string(sphereCount(in)); }});
    t.push_back({"RL_LIGHT_COUNT", kStructure, kSpecialised, {}, {}, "the light loop unrolled",
                 [](const DefineInput& in) -> Value { return std::to_string(in.scene.lights.size()); }});
    t.push_back({"RL_MAX_BOUNCES", kStructure, kSpecialised, {}, {},
                 "the bounce limit a constant; 0 folds traceRay's bounce code away",
                 [](const DefineInput& in) -> Value { return std::to_string(in.scene.render.maxBounces); }});
    t.push_back({"RL_FOR_EACH_SPHERE(X)", kStructure, kGeometryConstants, {}, {},
                 "the spheres written out one by one (closestHit, the shadow tests): every index, and with it "
                 "every sphere's numbers, a constant",
                 [](const DefineInput& in) -> Value {
                     return writesSpheresOut(in.scene) ? Value(forEachIndex(in.scene.spheres.size())) : kNone;
                 }});
    t.push_back({"RL_FOR_EACH_LIGHT(X)", kStructure, kGeometryConstants, {}, {},
                 "the lights written out one by one: each light's numbers and shadow tests fold",
                 [](const DefineInput& in) -> Value {
                     return writesLightsOut(in.scene) ? Value(forEachIndex(in.scene.lights.size())) : kNone;
                 }});
    t.push_back({"RL_SINGLE_SPHERE", kStructure, kSpecialised, {}, {},
                 "one convex sphere shadows only points seen from inside it: no shadow ray (lighting.glsl)",
                 [](const DefineInput& in) { return when(sphereCount(in) == 1); }});
    t.push_back({"RL_REFINE_SPHERES", kGeometry, kSpecialised, {}, {},
                 "closestHit() refines the roots of these spheres only (error_bounds.glsl), from the radii alone",
                 [](const DefineInput& in) { return refineSphereMask(in.scene); }});
    // Stopping the bounces early (trace.glsl) needs a bound on what a path
    // can bring back, derived for the reference model only
    // (render/bounce_cutoff.h). Its test costs about 5% of a lecture-scene
    // frame and, with at most two bounces, can rarely save one: after one or
    // two hits the throughput is still at least F0 = 0.04, or its square.
    t.push_back({"RL_BOUNCE_CUTOFF", kStructure | kModel, kSpecialised, {}, {},
                 "stop the bounces once no path can change a display step; from three bounces, reference model",
                 [](const DefineInput& in) {
                     // The bound R leaves environment light out: no cutoff with an environment.
                     return when(in.scene.render.maxBounces >= 3 && sphereCount(in) > 0 && in.scene.model.isReference() &&
                                 !in.scene.environment);
                 }});

    // ---- the scene's numbers as constants (scene.glsl; render/scene_constants.h): data
    // only, each a chain of selects on the index, the floats the uniform block would hold.
    // Geometry for the picture programs (the live view's panel does not edit it), values
    // for those that draw one picture (the live view's sliders edit them).
    t.push_back({"RL_SPHERE_GEOMETRY(i)", kGeometry, kGeometryConstants, {}, {},
                 "each sphere's centre and radius compiled in: what the ray tests share folds",
                 [](const DefineInput& in) -> Value { return spheresOrNone(in, sphereGeometryMacro); }});
    t.push_back({"RL_SPHERE_ANCHOR_C(i)", kGeometry, kGeometryConstants, {}, {},
                 "each sphere's |c|^2 - r^2 from the anchor, compiled in (error_bounds.glsl)",
                 [](const DefineInput& in) -> Value { return spheresOrNone(in, sphereAnchorCMacro); }});
    t.push_back({"RL_SPHERE_MATERIAL(i)", kValues, kOnePicture, {}, {},
                 "each sphere's material compiled in: the exercises' material terms fold",
                 [](const DefineInput& in) -> Value { return spheresOrNone(in, sphereMaterialMacro); }});
    t.push_back({"RL_SPHERE_EDGE_TINT(i)", kValues | kModel, kOnePicture, {"RL_MODEL_VARIANTS"}, {},
                 "each sphere's conductor edge tint compiled in (model_variants.glsl)",
                 [](const DefineInput& in) -> Value { return spheresOrNone(in, sphereEdgeTintMacro); }});
    t.push_back({"RL_LIGHT_POSITION(i)", kValues, kOnePicture, {}, {}, "each light's position compiled in",
                 [](const DefineInput& in) -> Value { return lightsOrNone(in, lightPositionMacro); }});
    t.push_back({"RL_LIGHT_INTENSITY(i)", kValues, kOnePicture, {}, {}, "each light's colour times intensity compiled in",
                 [](const DefineInput& in) -> Value { return lightsOrNone(in, lightIntensityMacro); }});
    t.push_back({"RL_LIGHT_SURFACE(k)", kValues | kGeometry, kOnePicture, {}, {},
                 "each light's nearness to a sphere's surface compiled in (docs/model.md, \"A light on a surface\")",
                 [](const DefineInput& in) -> Value { return lightsOrNone(in, lightSurfaceMacro); }});
    t.push_back({"RL_AMBIENT", kValues, kOnePicture, {}, {}, "the ambient factor compiled in",
                 [](const DefineInput& in) -> Value { return floatLiteral(float(in.scene.render.ambient)); }});
    t.push_back({"RL_BACKGROUND", kValues, kOnePicture, {}, {}, "the background compiled in",
                 [](const DefineInput& in) -> Value { return vec3Literal(glm::vec3(in.scene.render.background)); }});
    t.push_back({"RL_EXPOSURE", kValues, kOnePicture, {}, {}, "the exposure compiled in (display.glsl)",
                 [](const DefineInput& in) -> Value { return floatLiteral(float(in.scene.render.exposure)); }});
    t.push_back({"RL_TONE_MAP", kValues, kOnePicture, {}, {}, "the tone map compiled in: exercise 10's choice folds",
                 [](const DefineInput& in) -> Value { return std::to_string(int(in.scene.render.tonemap)); }});
    t.push_back({"RL_GAMMA", kValues, kOnePicture, {}, {}, "the gamma compiled in (0: sRGB): exercise 10's choice folds",
                 [](const DefineInput& in) -> Value {
                     return floatLiteral(in.scene.render.srgb ? 0.0f : float(in.scene.render.gamma));
                 }});

    // ---- one picture (or the live view's picture program), known before the program is built.
    t.push_back({"RL_PICTURE_ONLY", kPurpose | kFiles, kPicture | kLivePictures | kGenericPicture | kProbe, {}, {},
                 "no teaching term views (main.frag) and no per-ray fallback behind a started traceRay (trace.glsl)",
                 [](const DefineInput& in) {
                     // The checker's program serves the check of exercise 09 too,
                     // whose traceRay may still return NOT_STARTED for some rays:
                     // there only the course's own traceRay is trusted (the
                     // file of the unit that writes it, whatever its name).
                     if (in.purpose == Purpose::Probe) {
                         const ExerciseInfo* bounce = exerciseOfFunction("traceRay");
                         return when(bounce != nullptr && in.facts.courseFile(bounce->file()));
                     }
                     return kOne;
                 }});
    t.push_back({"RL_RESIDUAL_SPHERES", kGeometry, kPicture | kLivePictures, {}, {},
                 "makeHit()'s residual form only for huge spheres near the anchor (error_bounds.glsl)",
                 [](const DefineInput& in) { return residualSphereMask(in.scene); }, true, BenchLayer::Without});
    t.push_back({"RL_SAMPLE_GRID", kValues, kPicture | kLivePictures, {}, {},
                 "n x n samples a constant: sampleOffset()'s division and the loop bound fold (the live view "
                 "keeps a program per count)",
                 [](const DefineInput& in) -> Value { return sampleGrid(in.scene); }, true, BenchLayer::Without});
    t.push_back({"RL_CAMERA_FROM_ANCHOR", kCamera, kPicture, {}, {},
                 "the camera's position a constant: what the camera rays share folds (scene.glsl)",
                 [](const DefineInput& in) -> Value { return cameraFromAnchor(in.scene); }});
    t.push_back({"RL_CAMERA_SPHERE(i)", kCamera | kGeometry, kPicture, {}, {},
                 "each sphere's |camera - c|^2 - r^2 from double compiled in (error_bounds.glsl, issue #23)",
                 [](const DefineInput& in) -> Value { return spheresOrNone(in, cameraSphereMacro); }});
    t.push_back({"RL_CAMERA_RIGHT", kCamera, kPicture, {}, {},
                 "the camera's basis and the picture's size compiled in (camera.glsl): exercise 01's ray folds",
                 [](const DefineInput& in) -> Value { return cameraBasisColumn(in.scene, 0); }});
    t.push_back({"RL_CAMERA_UP", kCamera, kPicture, {}, {}, "(with RL_CAMERA_RIGHT)",
                 [](const DefineInput& in) -> Value { return cameraBasisColumn(in.scene, 1); }});
    t.push_back({"RL_CAMERA_BACK", kCamera, kPicture, {}, {}, "(with RL_CAMERA_RIGHT)",
                 [](const DefineInput& in) -> Value { return cameraBasisColumn(in.scene, 2); }});
    t.push_back({"RL_RESOLUTION", kCamera, kPicture, {}, {}, "(with RL_CAMERA_RIGHT)",
                 [](const DefineInput& in) -> Value {
                     return "vec2(" + floatLiteral(float(in.scene.render.width)) + ", " +
                            floatLiteral(float(in.scene.render.height)) + ")";
                 }});

    // ---- what the implementation's files allow (ImplementationFacts).
    t.push_back({"RL_EXERCISES_FINISHED", kFiles, kPicture | kLivePictures, {}, {},
                 "every exercise written, none names NOT_STARTED: the light terms summed by selects "
                 "(lighting.glsl; the GLSL itself has no stub test: shader/readiness.h)",
                 [](const DefineInput& in) { return when(in.facts.exercisesFinished); }, true, BenchLayer::Without});

    // ---- assumptions checked pixel by pixel: where one does not hold, the pixel is marked
    // and drawn again by the program without it (render/gl_renderer.h).
    // Shadow rays from the light's side (shadow_light_side.glsl): one dot product per
    // sphere against a constant, where the segment test takes four.
    t.push_back({"RL_SHADOW_STEPS(X, Y)", kGeometry | kValues | kStructure, kPicture | kLiveStill,
                 {"RL_FOR_EACH_LIGHT(X)"}, {},
                 "per sphere, the shadow test from the light's side (X) where it is exact for every light, or the "
                 "segment test (Y); at most 256 pairs of lights and spheres",
                 [](const DefineInput& in) { return shadowStepsMacro(in.scene); }, true, BenchLayer::Without});
    t.push_back({"RL_LIGHT_OCCLUDERS", kGeometry | kValues, kPicture | kLiveStill, {"RL_SHADOW_STEPS(X, Y)"}, {},
                 "per light and sphere, L - c and |L - c|^2 - r^2 from double (shadow_light_side.glsl)",
                 [](const DefineInput& in) -> Value { return lightOccludersArray(in.scene); }});
    // The screen tiles no camera ray of the model can reach a sphere in, drawn by the
    // picture program with no sphere to shade (RL_SKY, render/sky_tiles.h); each pixel
    // checks with the exercises' own camera ray and intersection that its ray misses.
    t.push_back({kSkyTilesDefine, kGeometry | kCamera, kPicture | kLiveStill, {}, {},
                 "screen tiles no camera ray can hit a sphere in drawn by the program without shading "
                 "(render/sky_tiles.h), each pixel's miss checked with the exercises' own code",
                 [](const DefineInput& in) { return when(sphereCount(in) > 0); }, false, BenchLayer::Without});
    return t;
}

}  // namespace

const char* purposeName(Purpose purpose) {
    switch (purpose) {
        case Purpose::Picture: return "picture";
        case Purpose::EveryView: return "every-view";
        case Purpose::LiveView: return "live-view";
        case Purpose::LiveStill: return "live-still";
        case Purpose::Probe: return "probe";
        case Purpose::GenericPicture: return "generic-picture";
        case Purpose::Generic: return "generic";
        case Purpose::PixelDebug: return "pixel-debug";
    }
    return "?";
}

const std::vector<DefineRow>& defineTable() {
    static const std::vector<DefineRow> table = makeTable();
    return table;
}

std::string glslName(const DefineRow& row) { return row.name.substr(0, row.name.find('(')); }

const std::vector<const char*>& nonSpecialisationNames() {
    static const std::vector<const char*> names = {
        "RL_PROBE_EXERCISE",    // probe.frag: the exercise the checker probes (checks/checker.cpp)
        "RL_MAX_SPHERES",       // scene.glsl: the uniform block's size, its own default
        "RL_MAX_LIGHTS",        // scene.glsl: the same for the lights
        "RL_LOOP_LIMIT",        // loop_guard.glsl: a constant of the runaway-loop guard (per run of a loop)
        "RL_LOOP_TOTAL_LIMIT",  // loop_guard.glsl: its total per invocation
        "RL_LOOP_TOTAL_FLAG",   // loop_guard.glsl: the mark that the total, not one loop, was met
        "RL_ADD_LIGHT",         // lighting.glsl: the X of RL_FOR_EACH_LIGHT
        "RL_NEAREST_STEP",      // intersect_scene.glsl: the X of RL_FOR_EACH_SPHERE in closestHit
        "RL_LIGHT_SIDE_STEP",   // intersect_scene.glsl: the X of RL_SHADOW_STEPS
        "RL_SEGMENT_STEP",      // intersect_scene.glsl: the Y of RL_SHADOW_STEPS
        "RL_SKY",               // main.frag, intersect_scene.glsl: the sky tiles' program (skyProgramDefines())
        "RL_MARKS_PIXELS",      // main.frag: the program marks the pixels whose assumption did not hold
        "RL_UNFINISHED",        // unfinished.glsl: a fact of the generated exercises.glsl (shader/readiness.h),
                                // like RL_READY_<function>, not a specialisation
        "RL_UNIT_LIGHT",        // lighting.glsl, trace.glsl: the same, when a unit adds a light term
        "RL_ENV_IRRADIANCE_MAP",  // environment.glsl: the bench's irradiance-map rows only (bench/environment_sweep.h)
    };
    return names;
}

ShaderDefines definesFor(const Scene& scene, const ImplementationFacts& facts, Purpose purpose) {
    if (!facts.traceStarted && purpose == Purpose::Picture) purpose = Purpose::EveryView;
    if (!facts.traceStarted && (purpose == Purpose::LiveView || purpose == Purpose::LiveStill)) purpose = Purpose::Generic;
    ShaderDefines defines;
    const DefineInput in{scene, facts, purpose, defines};
    for (const DefineRow& row : defineTable()) {
        if (!(row.purposes & purposeBit(purpose))) continue;
        if (std::any_of(row.needs.begin(), row.needs.end(), [&](const std::string& n) { return !defines.count(n); }))
            continue;
        if (std::any_of(row.excludes.begin(), row.excludes.end(), [&](const std::string& n) { return defines.count(n) != 0; }))
            continue;
        if (std::optional<std::string> value = row.value(in)) defines[row.name] = *value;
    }
    return defines;
}

ShaderDefines modelDefines(const ShadingModel& model) {
    Scene scene;
    scene.model = model;
    return definesFor(scene, ImplementationFacts{}, Purpose::Generic);
}

std::optional<ShaderDefines> skyProgramDefines(const ShaderDefines& picture) {
    if (!picture.count(kSkyTilesDefine) || !picture.count("RL_PICTURE_ONLY")) return std::nullopt;
    ShaderDefines sky = withoutAssumptions(picture);  // no hit is shaded: no shadow ray
    sky.erase(kSkyTilesDefine);
    sky["RL_SKY"] = "1";
    return sky;
}

bool marksPixels(const ShaderDefines& defines) {
    return defines.count("RL_SHADOW_STEPS(X, Y)") != 0 || defines.count("RL_SKY") != 0;
}

ShaderDefines withoutAssumptions(const ShaderDefines& defines) {
    ShaderDefines exact = defines;
    for (const char* name : {"RL_SHADOW_STEPS(X, Y)", "RL_LIGHT_OCCLUDERS", "RL_SKY", kSkyTilesDefine}) exact.erase(name);
    return exact;
}

}  // namespace rl
