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
#include "render/shader_config.h"

#include "core/float_range.h"

namespace rl {

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

}  // namespace rl

namespace rl {

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

}  // namespace rl
