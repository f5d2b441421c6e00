// ---- shader_config.cpp
#include "unit/old_defines.h"

namespace rl::old {

ShaderDefines shaderDefinesFor(const Scene& scene, bool specialise) {
    ShaderDefines defines = modelDefines(scene.model);
    if (specialise)
        for (const auto& [name, value] : specialisationDefines(scene)) defines[name] = value;
    return defines;
}

}  // namespace rl::old

// ---- model_defines.cpp
// The defines that select the model variants of shaders/model_variants.glsl
// (docs/model-variants.md). The reference model gets none, so its shader is
// the one it always was and every reference scene shares one program.
#include "unit/old_defines.h"

namespace rl::old {

ShaderDefines modelDefines(const ShadingModel& model) {
    ShaderDefines defines;
    if (model.isReference()) return defines;
    defines["RL_MODEL_VARIANTS"] = "1";  // raytracer.glsl includes model_variants.glsl
    if (model.blinnPhong) {
        // The whole BRDF is replaced and the other switches are ignored (as in
        // the CPU reference), so they add no define: scenes that differ only
        // in ignored switches share one program.
        defines["RL_BLINN_PHONG"] = "1";
        return defines;
    }
    switch (model.distribution) {
        case DistributionModel::GGX: break;
        case DistributionModel::Beckmann: defines["RL_D_BECKMANN"] = "1"; break;
    }
    switch (model.geometry) {
        case GeometryModel::SchlickGGX: break;
        case GeometryModel::SmithGGXSeparable: defines["RL_G_SMITH_SEPARABLE"] = "1"; break;
        case GeometryModel::SmithGGXCorrelated: defines["RL_G_SMITH_CORRELATED"] = "1"; break;
    }
    switch (model.fresnel) {
        case FresnelModel::Schlick: break;
        case FresnelModel::Dielectric: defines["RL_F_DIELECTRIC"] = "1"; break;
        case FresnelModel::Conductor: defines["RL_F_CONDUCTOR"] = "1"; break;
    }
    switch (model.diffuse) {
        case DiffuseModel::Lambert: break;
        case DiffuseModel::Burley: defines["RL_FD_BURLEY"] = "1"; break;
    }
    return defines;
}

}  // namespace rl::old

// ---- specialisation.cpp
// A shader specialised to a scene's structure: what the scene has (how many
// spheres and lights, the bounce limit, whether any sphere is a metal) is
// compiled in as constants, and code for what it lacks is left out. Values
// (positions, colours, roughness, intensities, exposure, the camera) stay
// uniforms, so editing them never recompiles: two scenes get different
// defines only when their structure differs. docs/performance.md measures it.
//
// Why constants pay on llvmpipe: a loop over a uniform count reads the
// uniform block with a per-lane gather in every iteration, and a constant
// count unrolls into direct loads; a feature left out costs nothing, while
// a feature behind a uniform branch costs its full price on a CPU rasteriser,
// which runs both sides of every branch under a mask.
#include "unit/old_defines.h"

#include "checks/exercise_registry.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/float_range.h"
#include "core/paths.h"
#include "render/shadow_cones.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace rl::old {

ShaderDefines specialisationDefines(const Scene& scene) {
    ShaderDefines d;
    int spheres = int(scene.spheres.size());
    int lights = int(scene.lights.size());
    int bounces = scene.render.maxBounces;
    d["RL_SPHERE_COUNT"] = std::to_string(spheres);  // scene.glsl: loops unrolled, uniform block read directly
    d["RL_LIGHT_COUNT"] = std::to_string(lights);
    d["RL_MAX_BOUNCES"] = std::to_string(bounces);   // 0: the bounce code of traceRay folds away

    bool metals = false;
    for (const Sphere& s : scene.spheres) metals = metals || s.material.metallic != 0.0;
    if (!metals) d["RL_NO_METALS"] = "1";  // metallic = 0: F0 = 0.04, no metal terms

    // One sphere is convex: it can shadow only points seen from inside it,
    // which needs no shadow ray (lighting.glsl). No lights: no shadow rays anyway.
    if (spheres == 1) d["RL_SINGLE_SPHERE"] = "1";

    // The spheres whose roots closestHit() refines (error_bounds.glsl): as a
    // constant mask the loop over the spheres, unrolled, drops the refinement
    // for every other sphere (on llvmpipe it would run masked for each).
    long mask = 0;
    bool fits = true;
    for (int i = 0; i < spheres; ++i)
        if (refinesRoots(scene, std::size_t(i))) {
            if (i < 31) mask |= 1L << i;
            else fits = false;
        }
    if (fits) d["RL_REFINE_SPHERES"] = std::to_string(mask);

    // Stopping the bounces early (trace.glsl) needs a bound on what a path can
    // bring back, derived for the reference model only (render/bounce_cutoff.h).
    // Its test costs about 5% of a lecture-scene frame (two tests per pixel,
    // llvmpipe runs them for every pixel) and, with at most two bounces, can
    // rarely save one: after one or two hits the throughput is still at least
    // F0 = 0.04, or its square. So it is compiled in from three bounces on.
    if (bounces >= 3 && spheres > 0 && scene.model.isReference()) d["RL_BOUNCE_CUTOFF"] = "1";

    return d;
}

ShaderDefines pictureOnlyDefines() {
    // main.frag: no teaching term views; trace.glsl: no per-ray fallback to
    // the first hit behind a started traceRay. On llvmpipe, which runs both
    // sides of every branch, each costs about a bounce per pixel even unused.
    return {{"RL_PICTURE_ONLY", "1"}};
}

namespace {

// Float32's unit roundoff and Higham's gamma_k, as in shaders/error_bounds.glsl.
constexpr double kUnitRoundoff = 5.9604644775390625e-8;
double roundingGamma(double k) { return k * kUnitRoundoff / (1.0 - k * kUnitRoundoff); }

// Whether makeHit()'s residual form can pay for some point of the sphere
// (shaders/error_bounds.glsl: it is taken where its bound is below the centre
// form's, gamma_12 (max|c_i| + 2r)), the sphere at `centre` relative to the
// scene's anchor (the origin of makeHit()'s coordinates, scene units). Over
// the points p of the sphere, with d = |c|:
//   residual bound >= gamma_10 (|C| + 2 max(d (d - r), 0) + (d - r)^2) / 2r
// (|p|.|c| >= p.c >= d (d - r), |p| >= |d - r|), and max|c_i| <= d. Both
// bounds are sound; the residual form is compiled in only where it can be
// 4 times smaller: a huge sphere near the anchor (a ground of radius 1000
// under the spheres: 4000 times), not a small sphere beside the anchor (at
// most 2.4 times, a few u r either way).
bool residualFormCandidate(glm::dvec3 centre, double radius) {
    double d = glm::length(centre);
    double cAnchor = (d - radius) * (d + radius);
    double residualAtBest = roundingGamma(10) *
                            (std::abs(cAnchor) + 2.0 * std::max(d * (d - radius), 0.0) + (d - radius) * (d - radius)) /
                            (2.0 * radius);
    return 4.0 * residualAtBest < roundingGamma(12) * (d + 2.0 * radius);
}

// A GLSL float literal that reads back as exactly x (9 significant digits
// round-trip a float32).
std::string floatLiteral(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(x));
    std::string literal = text;
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal;
}

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

}  // namespace

ShaderDefines residualSphereDefines(const Scene& scene) {
    int spheres = int(scene.spheres.size());
    if (spheres == 0 || spheres > 31) return {};  // the mask is one int
    const glm::dvec3 anchor = sceneAnchor(scene);  // makeHit() works in the anchor's frame
    long residual = 0;
    for (int i = 0; i < spheres; ++i)
        if (residualFormCandidate(scene.spheres[i].center - anchor, scene.spheres[i].radius)) residual |= 1L << i;
    return {{"RL_RESIDUAL_SPHERES", std::to_string(residual)}};
}

ShaderDefines sampleGridDefines(const Scene& scene) {
    // Samples per pixel: n x n, a constant, so that sampleOffset()'s integer
    // division (emulated on a CPU's vector units) and the loop's bound fold.
    return {{"RL_SAMPLE_GRID", std::to_string(std::max(1, int(std::lround(std::sqrt(double(scene.render.spp))))))}};
}

ShaderDefines pictureValueDefines(const Scene& scene) {
    ShaderDefines d = residualSphereDefines(scene);
    d.merge(sampleGridDefines(scene));
    // The camera's position relative to the anchor, the float32 value the
    // scene block holds (SceneUniformBlock::upload): what the camera rays
    // share folds (scene.glsl, cameraFromAnchor).
    const glm::vec3 camera = shaderPosition(scene.camera.position, sceneAnchor(scene),
                                            shaderUnits(scene, scene.camera.position).unit);
    d["RL_CAMERA_FROM_ANCHOR"] = "vec3(" + floatLiteral(camera.x) + ", " + floatLiteral(camera.y) + ", " +
                                 floatLiteral(camera.z) + ")";
    return d;
}

ShaderDefines finishedExerciseDefines(const Implementation& impl) {
    constexpr std::uintmax_t kLargestExercise = 1 << 20;  // a larger file is read by the compiler, not here
    for (const ExerciseInfo& exercise : allExercises()) {
        std::filesystem::path file = impl.fileFor(exercise.file());
        if (isUnchangedStub(file, exercise)) return {};
        try {
            if (namesIdentifier(withoutComments(readRegularFile(file, kLargestExercise)), "NOT_STARTED")) return {};
        } catch (const Error&) {
            return {};  // unreadable: the compiler says why
        }
    }
    return {{"RL_EXERCISES_FINISHED", "1"}};
}

// Whether two implementations have the same text for an exercise file (white
// space aside, as isUnchangedStub() compares).
bool sameExercise(const Implementation& a, const Implementation& b, const std::string& file) {
    constexpr std::uintmax_t kLargestExercise = 1 << 20;
    try {
        return normalisedGlsl(readRegularFile(a.fileFor(file), kLargestExercise)) ==
               normalisedGlsl(readRegularFile(b.fileFor(file), kLargestExercise));
    } catch (const Error&) {
        return false;
    }
}

// Whether `impl`'s exercise file is the course's solution (its text, white space aside).
bool courseExercise(const Implementation& impl, const std::string& file) {
    return sameExercise(impl, Implementation{solutionsDir(), {}}, file);
}

// The most shadow cones (lights x spheres) a program for one picture writes
// out (renderProgramDefines() says why).
constexpr std::size_t kShadowConeBudget = 256;

// From how many spheres on the candidate loop of the shadow rays pays
// (docs/performance.md; the bench's layers sweep measures both sides).
constexpr int kCandidateShadowSpheres = 12;

ShaderDefines fileDefines(const Implementation& impl) {
    ShaderDefines defines = finishedExerciseDefines(impl);
    // Shadow rays need whether, not where: with the course's own 02 (the host
    // compares the file), a closed-form segment test without the root
    // (intersect_scene.glsl); a student's intersectSphere() stays in every ray.
    if (courseExercise(impl, "02-intersect.glsl")) defines["RL_SEGMENT_TEST"] = "1";
    return defines;
}

ShaderDefines implementationDefines(const Scene& scene, const ShaderDefines& files) {
    ShaderDefines defines = files;
    // Shadow rays ask every sphere a cheap question first and run the test
    // proper in a loop over the spheres that pass (intersect_scene.glsl): a
    // sphere mask is one int, and only with every exercise written.
    int spheres = int(scene.spheres.size());
    if (defines.count("RL_EXERCISES_FINISHED") && spheres <= 31) {
        if (spheres >= kCandidateShadowSpheres && !scene.lights.empty()) defines["RL_CANDIDATE_SHADOWS"] = "1";
    }
    // The direct light's sum by selects, not branches (lighting.glsl): with
    // no stub (a shadow ray cast for a light facing away would mark a stub's
    // frame) and unrolled shadow tests (the candidate loop would then turn
    // for lights that add nothing: 8% slower on 30 spheres).
    if (defines.count("RL_EXERCISES_FINISHED") && !defines.count("RL_CANDIDATE_SHADOWS")) defines["RL_SELECT_LIGHTS"] = "1";
    return defines;
}

namespace {

// RL_SHADOW_CONES: the cones as constant arrays, and the lights expanded
// one by one (RL_FOR_EACH_LIGHT), so that every index into them is a
// constant. Indexed by a variable, a constant array is copied into every
// pixel's memory: 20 times slower on llvmpipe.
ShaderDefines shadowConeDefines(const Scene& scene) {
    std::string axes, nearest, lights, spheres;
    for (const ShadowCone& c : shadowCones(scene)) {
        const char* comma = axes.empty() ? "" : ", ";
        axes += comma + ("vec4(" + floatLiteral(c.axis.x) + ", " + floatLiteral(c.axis.y) + ", " + floatLiteral(c.axis.z) +
                         ", " + floatLiteral(c.minCos) + ")");
        nearest += comma + floatLiteral(c.nearest);
    }
    for (std::size_t k = 0; k < scene.lights.size(); ++k) lights += " X(" + std::to_string(k) + ")";
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) spheres += " X(" + std::to_string(i) + ")";
    return {{"RL_SHADOW_CONES", "1"},
            {"RL_SHADOW_CONE_AXIS", "vec4[](" + axes + ")"},
            {"RL_SHADOW_CONE_NEAREST", "float[](" + nearest + ")"},
            {"RL_FOR_EACH_LIGHT(X)", lights},
            {"RL_FOR_EACH_SPHERE(X)", spheres}};
}

// Whether the camera lies outside every sphere by more than float32 can blur:
// the shader holds the camera and the centres relative to the anchor, each
// rounded by u of its distance from it; 1e-6 of those distances is 16 times that.
bool cameraOutsideEverySphere(const Scene& scene) {
    const glm::dvec3 anchor = sceneAnchor(scene), eye = scene.camera.position;
    return std::all_of(scene.spheres.begin(), scene.spheres.end(), [&](const Sphere& s) {
        double blur = 1e-6 * (glm::length(eye - anchor) + glm::length(s.center - anchor) + s.radius);
        return glm::length(eye - s.center) - s.radius > blur;
    });
}

}  // namespace

bool traceStarted(const Implementation& impl) {
    const ExerciseInfo& reflections = findExercise("9");
    return !isUnchangedStub(impl.fileFor(reflections.file()), reflections);
}

ShaderDefines renderProgramDefines(const Scene& scene, const Implementation& impl) {
    ShaderDefines defines = shaderDefinesFor(scene, true);
    if (!traceStarted(impl)) return defines;
    for (const ShaderDefines& more : {pictureOnlyDefines(), pictureValueDefines(scene), implementationDefines(scene, fileDefines(impl))})
        for (const auto& [name, value] : more) defines[name] = value;
    // The sky tiles follow the course's camera rays and roots: only with the
    // course's own 01 and 02 (a student's camera or intersection draws every
    // pixel itself, so that its mistakes show everywhere). RL_SEGMENT_TEST
    // says 02 is the course's (fileDefines()); 04 is read once for the two
    // layers after this one.
    const bool course02 = defines.count("RL_SEGMENT_TEST") != 0;
    const bool course04 = courseExercise(impl, "04-shadows.glsl");
    if (course02 && courseExercise(impl, "01-camera.glsl")) defines[kSkyTilesDefine] = "1";
    // Every hit seen from outside (intersect_scene.glsl, closestHit): the
    // camera outside every sphere, and the course's own intersection, ray
    // offset and bounce, so that no student's ray can start inside a sphere
    // (a student's mistake there shows as it does in every other program).
    if (cameraOutsideEverySphere(scene) && course02 && course04 && courseExercise(impl, "09-reflections.glsl"))
        defines["RL_CAMERA_OUTSIDE"] = "1";
    // The shadow rays' candidates by their cones from each light
    // (render/shadow_cones.h), from two spheres on (one casts no shadow ray):
    // with every exercise written and the course's own segment test and
    // shadow ray, whose ray from the offset point to the light the cones
    // assume. A cone costs a dot product against a constant, so the candidate
    // loop pays from two spheres on, where mayHitSphere() pays from 12 (the
    // live view's). It replaces the light sum by selects (RL_SELECT_LIGHTS),
    // which needs the shadow tests unrolled.
    // Each cone is a test written out per light and sphere, and Mesa's compile
    // time grows faster than their count: with no shader cache, building and
    // the first draw take 0.25 s for the lecture's 12 (2 lights, 6 spheres),
    // 0.62 s for 180 (6 x 30), 0.84 s for 256 (4 x 64) and 8.9 s for 1024
    // (16 x 64), which no frame saving repays. So at most kShadowConeBudget.
    const std::size_t spheres = scene.spheres.size();
    if (defines.count("RL_EXERCISES_FINISHED") && course02 && course04 && spheres >= 2 && spheres <= 3 * 31 &&
        !scene.lights.empty() && spheres * scene.lights.size() <= kShadowConeBudget) {
        defines["RL_CANDIDATE_SHADOWS"] = "1";
        defines.erase("RL_SELECT_LIGHTS");
        defines.merge(shadowConeDefines(scene));
    }
    return defines;
}

std::optional<ShaderDefines> skyProgramDefines(const ShaderDefines& picture) {
    if (!picture.count(kSkyTilesDefine) || !picture.count("RL_PICTURE_ONLY")) return std::nullopt;
    ShaderDefines sky = picture;
    sky["RL_SPHERE_COUNT"] = "0";  // every camera ray misses: the rest of the program is the picture's
    for (const char* name : {"RL_SINGLE_SPHERE", "RL_REFINE_SPHERES", "RL_RESIDUAL_SPHERES", "RL_CANDIDATE_SHADOWS",
                             "RL_SHADOW_CONES", "RL_SHADOW_CONE_AXIS", "RL_SHADOW_CONE_NEAREST", "RL_FOR_EACH_LIGHT(X)",
                             "RL_FOR_EACH_SPHERE(X)"})
        sky.erase(name);
    return sky;
}

ShaderDefines structuralDefines(const Scene& scene) {
    // The live view's specialisation (app/render/live_defines.cpp): of
    // specialisationDefines(), only what follows from the scene's structure,
    // never from a value the view's panel edits: the counts, the bounce
    // limit, what the model implies, and which spheres are the huge ones
    // whose roots are refined (RL_REFINE_SPHERES: from the radii alone,
    // which the panel does not edit; a ground sphere stays one). Left out:
    // RL_NO_METALS (every metallic 0), which the metallic slider changes.
    // A whitelist, so that a value-dependent define added to
    // specialisationDefines() later never reaches the live view unseen.
    static const char* const kStructural[] = {"RL_SPHERE_COUNT",  "RL_LIGHT_COUNT",   "RL_MAX_BOUNCES",
                                               "RL_SINGLE_SPHERE", "RL_BOUNCE_CUTOFF", "RL_REFINE_SPHERES"};
    const ShaderDefines all = specialisationDefines(scene);
    ShaderDefines d;
    for (const char* name : kStructural)
        if (auto it = all.find(name); it != all.end()) d[name] = it->second;
    return d;
}

}  // namespace rl::old

// ---- live_defines.cpp
#include "unit/old_defines.h"

namespace rl::old {


ShaderDefines liveViewDefines(const Scene& scene, const ShadingModel& model, View view, bool traceStarted,
                             const ShaderDefines& files) {
    ShaderDefines defines = modelDefines(model);
    if (!traceStarted || !rl::isPictureView(view)) return defines;  // the generic program (live_defines.h says why)
    for (const ShaderDefines& more : {structuralDefines(scene), residualSphereDefines(scene), sampleGridDefines(scene),
                                       pictureOnlyDefines(), implementationDefines(scene, files)})
        for (const auto& [name, value] : more) defines[name] = value;
    return defines;
}

}  // namespace rl::old

