// The table of every RL_ define (render/define_table.h). One row per define,
// in the order they are decided; the reasons are the short form of the
// comments the shaders carry where each is read, and of docs/performance.md.
#include "render/define_table.h"

#include "render/define_values.h"

#include <algorithm>

namespace rl {

namespace {

using Value = std::optional<std::string>;
const Value kOne = std::string("1");
const Value kNone = std::nullopt;

Value when(bool condition) { return condition ? kOne : kNone; }
bool has(const DefineInput& in, const char* name) { return in.sofar.count(name) != 0; }

constexpr unsigned kPicture = purposeBit(Purpose::Picture);
constexpr unsigned kEveryView = purposeBit(Purpose::EveryView);
constexpr unsigned kLive = purposeBit(Purpose::LiveView);
constexpr unsigned kProbe = purposeBit(Purpose::Probe);
constexpr unsigned kGenericPicture = purposeBit(Purpose::GenericPicture);
constexpr unsigned kGeneric = purposeBit(Purpose::Generic);
// The model is compiled into every program drawn for a scene; the checker's
// one program serves every check scene, so it has none.
constexpr unsigned kEveryScene = kPicture | kEveryView | kLive | kGenericPicture | kGeneric;
// What a specialised program compiles in.
constexpr unsigned kSpecialised = kPicture | kEveryView | kLive;

int sphereCount(const DefineInput& in) { return int(in.scene.spheres.size()); }

bool hasMetal(const Scene& scene) {
    return std::any_of(scene.spheres.begin(), scene.spheres.end(),
                       [](const Sphere& s) { return s.material.metallic != 0.0; });
}

// The shadow cones fit: two spheres or more (one casts no shadow ray), up to
// three mask words of spheres, a light, and at most kShadowConeBudget cones.
bool conesFit(const Scene& scene) {
    const std::size_t spheres = scene.spheres.size();
    return spheres >= 2 && spheres <= 3 * 31 && !scene.lights.empty() &&
           spheres * scene.lights.size() <= kShadowConeBudget;
}

// The candidate loop without cones needs a sphere mask (one int) and a light.
bool candidateLoopFits(const Scene& scene) { return scene.spheres.size() <= 31 && !scene.lights.empty(); }

std::vector<DefineRow> makeTable() {
    std::vector<DefineRow> t;

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

    // ---- the scene's structure (scene.glsl): loops unrolled, the uniform block read directly.
    t.push_back({"RL_SPHERE_COUNT", kStructure, kSpecialised, {}, {},
                 "the sphere loops unrolled with direct loads instead of a per-lane gather per iteration",
                 [](const DefineInput& in) -> Value { return std::to_string(sphereCount(in)); },
                 true, InSky::Zero});
    t.push_back({"RL_LIGHT_COUNT", kStructure, kSpecialised, {}, {}, "the light loop unrolled",
                 [](const DefineInput& in) -> Value { return std::to_string(in.scene.lights.size()); }});
    t.push_back({"RL_MAX_BOUNCES", kStructure, kSpecialised, {}, {},
                 "the bounce limit a constant; 0 folds traceRay's bounce code away",
                 [](const DefineInput& in) -> Value { return std::to_string(in.scene.render.maxBounces); }});
    t.push_back({"RL_NO_METALS", kValues, kPicture | kEveryView, {}, {},
                 "every metallic 0: F0 = 0.04, no metal terms (the live view's slider edits metallic)",
                 [](const DefineInput& in) { return when(!hasMetal(in.scene)); }});
    t.push_back({"RL_SINGLE_SPHERE", kStructure, kSpecialised, {}, {},
                 "one convex sphere shadows only points seen from inside it: no shadow ray (lighting.glsl)",
                 [](const DefineInput& in) { return when(sphereCount(in) == 1); }, true, InSky::Dropped});
    t.push_back({"RL_REFINE_SPHERES", kGeometry, kSpecialised, {}, {},
                 "closestHit() refines the roots of these spheres only (error_bounds.glsl), from the radii alone",
                 [](const DefineInput& in) { return refineSphereMask(in.scene); }, true, InSky::Dropped});
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

    // ---- one picture (or the live view's picture program), known before the program is built.
    t.push_back({"RL_PICTURE_ONLY", kPurpose | kFiles, kPicture | kLive | kGenericPicture | kProbe, {}, {},
                 "no teaching term views (main.frag) and no per-ray fallback behind a started traceRay (trace.glsl)",
                 [](const DefineInput& in) {
                     // The checker's program serves the check of exercise 09 too,
                     // whose traceRay may still return NOT_STARTED for some rays:
                     // there only the course's own 09 is trusted.
                     if (in.purpose == Purpose::Probe) return when(in.facts.courseFile("09-reflections.glsl"));
                     return kOne;
                 }});
    t.push_back({"RL_RESIDUAL_SPHERES", kGeometry, kPicture | kLive, {}, {},
                 "makeHit()'s residual form only for huge spheres near the anchor (error_bounds.glsl)",
                 [](const DefineInput& in) { return residualSphereMask(in.scene); }, true, InSky::Dropped,
                 BenchLayer::Without});
    t.push_back({"RL_SAMPLE_GRID", kValues, kPicture | kLive, {}, {},
                 "n x n samples a constant: sampleOffset()'s division and the loop bound fold (the live view "
                 "keeps a program per count)",
                 [](const DefineInput& in) -> Value { return sampleGrid(in.scene); }, true, InSky::Kept,
                 BenchLayer::Without});
    t.push_back({"RL_CAMERA_FROM_ANCHOR", kCamera, kPicture, {}, {},
                 "the camera's position a constant: what the camera rays share folds (scene.glsl)",
                 [](const DefineInput& in) -> Value { return cameraFromAnchor(in.scene); }});

    // ---- what the implementation's files allow (ImplementationFacts).
    t.push_back({"RL_EXERCISES_FINISHED", kFiles, kPicture | kLive, {}, {},
                 "every exercise written, none names NOT_STARTED: what the specialisations below assume "
                 "(the GLSL itself has no stub test: shader/readiness.h)",
                 [](const DefineInput& in) { return when(in.facts.exercisesFinished); }, false, InSky::Kept,
                 BenchLayer::Without});
    t.push_back({"RL_SEGMENT_TEST", kFiles, kPicture | kLive, {}, {},
                 "shadow rays need whether, not where: with the course's 02, a segment test without the root",
                 [](const DefineInput& in) { return when(in.facts.courseFile("02-intersect.glsl")); }, true,
                 InSky::Kept, BenchLayer::Without});
    // The sky tiles follow the course's camera rays and roots: a student's
    // camera or intersection draws every pixel itself, so that its mistakes
    // show everywhere.
    t.push_back({kSkyTilesDefine, kFiles | kGeometry | kCamera, kPicture, {}, {},
                 "screen tiles no camera ray can hit a sphere in drawn by a program without spheres "
                 "(render/sky_tiles.h), with the course's 01 and 02",
                 [](const DefineInput& in) {
                     return when(in.facts.courseFile("01-camera.glsl") && in.facts.courseFile("02-intersect.glsl"));
                 },
                 false, InSky::Kept, BenchLayer::Without});
    // No student's ray can start inside a sphere with the course's
    // intersection, ray offset and bounce (a student's mistake there shows as
    // it does in every other program).
    t.push_back({"RL_CAMERA_OUTSIDE", kCamera | kGeometry | kFiles, kPicture, {}, {},
                 "every hit seen from outside (closestHit): the camera outside every sphere, the course's 02, 04, 09",
                 [](const DefineInput& in) {
                     const ImplementationFacts& f = in.facts;
                     return when(cameraOutsideEverySphere(in.scene) && f.courseFile("02-intersect.glsl") &&
                                 f.courseFile("04-shadows.glsl") && f.courseFile("09-reflections.glsl"));
                 },
                 true, InSky::Kept, BenchLayer::Without});
    // The shadow rays' candidates by their cones from each light
    // (render/shadow_cones.h), with the course's own segment test and shadow
    // ray, whose ray from the offset point to the light the cones assume. A
    // cone costs a dot product against a constant, so the candidate loop
    // pays from two spheres on. Each cone is a test written out per light and
    // sphere, and Mesa's compile time grows faster than their count: with no
    // shader cache, building and the first draw take 0.25 s for the
    // lecture's 12 (2 lights, 6 spheres), 0.62 s for 180 (6 x 30), 0.84 s for
    // 256 (4 x 64) and 8.9 s for 1024 (16 x 64), which no frame saving
    // repays. So at most kShadowConeBudget.
    t.push_back({"RL_SHADOW_CONES", kGeometry | kValues | kStructure | kFiles, kPicture, {"RL_EXERCISES_FINISHED"}, {},
                 "shadow-ray candidates by constant cones from each light, with the course's 02 and 04, "
                 "at most 256 cones",
                 [](const DefineInput& in) {
                     return when(in.facts.courseFile("02-intersect.glsl") && in.facts.courseFile("04-shadows.glsl") &&
                                 conesFit(in.scene));
                 },
                 true, InSky::Dropped, BenchLayer::Without});
    t.push_back({"RL_SHADOW_CONE_AXIS", kGeometry | kValues, kPicture, {"RL_SHADOW_CONES"}, {},
                 "the cones' axes and cosines, light-major, as a constant array",
                 [](const DefineInput& in) -> Value { return shadowConeAxes(in.scene); }, true, InSky::Dropped});
    t.push_back({"RL_SHADOW_CONE_NEAREST", kGeometry | kValues, kPicture, {"RL_SHADOW_CONES"}, {},
                 "the cones' nearest distances, light-major, as a constant array",
                 [](const DefineInput& in) -> Value { return shadowConeNearest(in.scene); }, true, InSky::Dropped});
    t.push_back({"RL_FOR_EACH_LIGHT(X)", kStructure, kPicture, {"RL_SHADOW_CONES"}, {},
                 "the lights expanded one by one, so that every index into the cones is a constant",
                 [](const DefineInput& in) -> Value { return forEachIndex(in.scene.lights.size()); }, true,
                 InSky::Dropped});
    t.push_back({"RL_FOR_EACH_SPHERE(X)", kStructure, kPicture, {"RL_SHADOW_CONES"}, {},
                 "the spheres expanded one by one, so that every index into the cones is a constant",
                 [](const DefineInput& in) -> Value { return forEachIndex(in.scene.spheres.size()); }, true,
                 InSky::Dropped});
    // Shadow rays ask every sphere a cheap question first and run the test
    // proper in a loop over the spheres that pass (intersect_scene.glsl).
    DefineRow candidates{"RL_CANDIDATE_SHADOWS", kStructure | kFiles, kPicture | kLive, {"RL_EXERCISES_FINISHED"}, {},
                         "shadow rays test only candidate spheres: by the cones, or by mayHitSphere() from 12 spheres",
                         [](const DefineInput& in) {
                             return when(has(in, "RL_SHADOW_CONES") ||
                                         (sphereCount(in) >= kCandidateShadowSpheres && candidateLoopFits(in.scene)));
                         },
                         true, InSky::Dropped, BenchLayer::Without};
    candidates.benchWith = candidateLoopFits;  // the threshold's other side
    t.push_back(candidates);
    // With a stub, a shadow ray cast for a light facing away would mark a
    // stub's frame; with the candidate loop, it would turn for lights that
    // add nothing (8% slower on 30 spheres).
    t.push_back({"RL_SELECT_LIGHTS", kFiles | kStructure, kPicture | kLive, {"RL_EXERCISES_FINISHED"},
                 {"RL_CANDIDATE_SHADOWS"},
                 "the direct light summed by selects, not branches (lighting.glsl), with unrolled shadow tests",
                 [](const DefineInput&) { return kOne; }, true, InSky::Kept, BenchLayer::Without});
    return t;
}

}  // namespace

const char* purposeName(Purpose purpose) {
    switch (purpose) {
        case Purpose::Picture: return "picture";
        case Purpose::EveryView: return "every-view";
        case Purpose::LiveView: return "live-view";
        case Purpose::Probe: return "probe";
        case Purpose::GenericPicture: return "generic-picture";
        case Purpose::Generic: return "generic";
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
        "RL_PIXEL_DEBUG",       // pixel_debug.frag: the pixel debugger's recorder (render/pixel_debugger.cpp)
        "RL_MAX_SPHERES",       // scene.glsl: the uniform block's size, its own default
        "RL_MAX_LIGHTS",        // scene.glsl: the same for the lights
        "RL_LOOP_LIMIT",        // loop_guard.glsl: a constant of the runaway-loop guard (per run of a loop)
        "RL_LOOP_TOTAL_LIMIT",  // loop_guard.glsl: its total per invocation
        "RL_LOOP_TOTAL_FLAG",   // loop_guard.glsl: the mark that the total, not one loop, was met
        "RL_ADD_LIGHT",         // lighting.glsl: the X of RL_FOR_EACH_LIGHT
        "RL_SHADOW_CANDIDATE",  // intersect_scene.glsl: the X of RL_FOR_EACH_SPHERE
        "RL_UNFINISHED",        // unfinished.glsl: a fact of the generated exercises.glsl (shader/readiness.h),
                                // like RL_READY_<function>, not a specialisation
        "RL_UNIT_LIGHT",        // lighting.glsl, trace.glsl: the same, when a unit adds a light term
        "RL_ENV_IRRADIANCE_MAP",  // environment.glsl: the bench's irradiance-map rows only (bench/environment_sweep.h)
    };
    return names;
}

ShaderDefines definesFor(const Scene& scene, const ImplementationFacts& facts, Purpose purpose) {
    if (!facts.traceStarted && purpose == Purpose::Picture) purpose = Purpose::EveryView;
    if (!facts.traceStarted && purpose == Purpose::LiveView) purpose = Purpose::Generic;
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
    ShaderDefines sky = picture;
    for (const DefineRow& row : defineTable()) {
        auto it = sky.find(row.name);
        if (it == sky.end()) continue;
        if (row.inSky == InSky::Dropped) sky.erase(it);
        if (row.inSky == InSky::Zero) it->second = "0";  // every camera ray misses: the rest is the picture's
    }
    return sky;
}

}  // namespace rl
