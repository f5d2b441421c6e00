// cpu_reference.h: the double-precision CPU renderer of the reference model
// (docs/model.md): visibility, direct light, the mirror
// bounces and the display step, built on the terms of brdf_reference.h.
// It shares no code with the GLSL; every check compares the shader against it.
//
// Colour spaces: every dvec3 returned here is LINEAR radiance, except
// Rendering::display (8-bit, display-encoded).
#pragma once

#include "core/image.h"
#include "core/scene.h"
#include "reference/brdf_reference.h"

#include <glm/vec3.hpp>

#include <cstdint>

namespace rl::ref {

// False in a student edition built without the reference's sources
// (app/reference/absent.cpp, docs/instructor.md "A student edition"): every
// function of this layer then throws rl::Error "not in this copy: ...", and
// what needs its values reads them from what the instructor's build recorded.
bool referenceInThisCopy();

// How the reference integrates a scene's environment light (defined in
// environment_reference.h; the defaults: 256 samples a strategy, seed 1,
// with visibility). Scenes without an environment never look at it.
struct EnvironmentOptions;

// A ray/sphere hit.
struct Hit {
    double t = kNoHit;      // distance along the unit ray direction; kNoHit for a miss
    glm::dvec3 p{0.0};      // hit point, world space, reprojected onto the sphere: centre + radius u
    glm::dvec3 n{0.0};      // unit normal u = (p - centre)/radius, flipped to face the incoming ray
    double magnitude = 0;   // max(maxAbs(p), maxAbs(centre) + radius): the scale of the numbers behind p
    int sphere = -1;        // index into Scene::spheres
    bool inside = false;    // the ray met the sphere from inside (its far root): n = -u
    double error = 0;       // bound on the distance of p from the true surface (double rounding only)
    bool hasTwin = false;   // another sphere has the same centre and radius (the same surface)
};

// ---- visibility ------------------------------------------------------------------
//
// The geometric truth (spec "Reflection bounces"): a ray that leaves a
// sphere's surface on the outside cannot meet that sphere again (it is
// convex), and one that leaves it on the inside meets it once more, at its
// far root t = -2 (p - centre).w (the near root is 0). Secondary rays are
// therefore traced with the sphere they leave (and any identical one)
// handled exactly, never behind an offset; the other spheres see the origin
// pushed along n by Hit::error, a bound on double rounding (4e-15 of the
// scene's size), so that a surface within rounding of the one left (a copy
// of a sphere whose centre rounded differently) does not shadow it; it
// changes no pixel.
// This is the reference's own geometry, independent of the GLSL.

// Nearest sphere hit with t > 0 along the unit direction dir from a point
// on no surface (a camera ray). Fills `out` and returns true, or returns
// false (and leaves `out` alone) on a miss.
bool closestHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, Hit& out);

// Nearest hit of the secondary ray that leaves the surface at `from` in the
// unit direction dir, on the side n faces (dot(dir, from.n) >= 0: a mirror
// bounce or a shadow ray towards a light above the surface). The sphere it
// leaves is handled exactly (see above). Same contract as closestHit.
bool nextHit(const Scene& scene, const Hit& from, glm::dvec3 dir, Hit& out);

// True when some sphere is hit at 0 < t < tMax along the unit direction dir.
// Stops at the first occluder: a shadow ray needs whether, not where.
bool anyHitBefore(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, double tMax);

// Exercise 04's lightVisibility(), as the exercise teaches it: true when
// nothing lies between the hit and the light, the shadow ray starting at
// offsetRayOrigin(p, n, magnitude). The exercise probes check the student's
// function against this one; the renderer below uses lightReachable().
bool lightVisible(const Scene& scene, const Hit& hit, glm::dvec3 lightPosition);

// The reference's shadow ray: true when no surface lies between the hit and
// the light, with the sphere of the hit handled exactly (from outside it
// cannot occlude; from inside its far root occludes when nearer than the
// light). Call it only for a light above the surface (n.l > 0).
bool lightReachable(const Scene& scene, const Hit& hit, glm::dvec3 lightPosition);

// ---- shading ---------------------------------------------------------------------

// Direct light of every point light at the hit, towards v = -dir:
//     sum over visible lights of f(n, v, l) E,  E = pointLightIrradiance(p, n, c, C I)
// with f = cookTorranceBRDF(..., scene.model) (so every model variant applies).
// Without the ambient term.
glm::dvec3 directLight(const Scene& scene, const Hit& hit, glm::dvec3 v);

// What one hit sends towards v: directLight + ambient * albedo * ao (the
// ambient term once per hit, lit or not).
glm::dvec3 shadeHit(const Scene& scene, const Hit& hit, glm::dvec3 v);

// Radiance arriving at `origin` along -dir (dir a unit vector), spec
// "Reflection bounces": the primary hit and up to render.maxBounces mirror
// bounces, each hit adding throughput * shadeHit; after each hit
//     throughput *= F_SchlickRoughness(F0, clamp(n.(-d), 1e-4, 1), roughness)
// and the ray continues from p in normalize(reflect(d, n)) (nextHit(): no
// offset; renormalised so that |d| = 1 does not drift over many bounces).
// A ray that hits nothing adds throughput * background and stops.
// The bounce Fresnel is F_SchlickRoughness for EVERY model variant: the
// variants (scene.model) change the direct-light BRDF only.
// With scene.environment (docs/model.md, "Environment light"): a camera ray
// that hits nothing adds the environment's radiance instead of background; each
// hit adds throughput * environmentLight() (environment_reference.h) too; a
// bounce that escapes adds nothing (its direction is part of that integral).
// Its estimates are seeded by options.seed and the bits of (origin, dir).
glm::dvec3 traceRadiance(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir);
glm::dvec3 traceRadiance(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, const EnvironmentOptions& options);

// ---- the camera and the whole picture ---------------------------------------------------

// Orthonormal camera basis (spec "Camera"): forward = normalize(target - position),
// right = normalize(cross(forward, up)), up = cross(right, forward).
// Throws rl::Error when target = position or up is parallel to the view.
struct CameraBasis {
    glm::dvec3 position{0.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    double fovYRadians = 0;  // full vertical field of view
};
CameraBasis cameraBasis(const Camera& camera);

// Radiance of pixel (i, j), column i from the left, row j from the BOTTOM:
// the average of traceRadiance over the render.spp = n*n samples at
// sampleOffset(s, n).
glm::dvec3 pixelRadiance(const Scene& scene, const CameraBasis& camera, int i, int j);
glm::dvec3 pixelRadiance(const Scene& scene, const CameraBasis& camera, int i, int j, const EnvironmentOptions& options);

// Renders the scene at render.width x render.height: averaged linear radiance
// (as float) and its display step in double, quantised by rl::quantize8.
// Pixel (i, j) (j from the bottom) lands in image row height - 1 - j (row 0 = top).
// Rows are shared among `threads` worker threads (0: hardware_concurrency());
// the result does not depend on the thread count.
// Throws rl::Error for a non-positive size or spp, or a degenerate camera.
Rendering renderCpu(const Scene& scene, int threads = 0);
Rendering renderCpu(const Scene& scene, int threads, const EnvironmentOptions& options);

// ---- energy ------------------------------------------------------------------------------

// Directional albedo of the BRDF: the integral over the hemisphere of
//     f(n, v, l) NoL dl,   NoV = n.v given (0 < NoV <= 1)
// for cookTorranceBRDF(..., model), by deterministic stratified quadrature on
// samples x samples cells per lobe: the diffuse lobe over cosine-distributed
// l, the specular lobe over h distributed as the model's D NoH (GGX,
// Beckmann or Blinn-Phong), mapped to l by reflection (dl = 4 VoH dh). That
// importance mapping resolves the lobe at r = 0.045 (width alpha = 0.002 rad),
// which a uniform grid in (cos theta, phi) misses. Returns the albedo per
// channel (<= 1 for an energy-conserving BRDF).
glm::dvec3 directionalAlbedo(double NoV, const Material& material, const ShadingModel& model, int samples);

// The same for F0 and metallic given: albedo solved from F0 = mix(0.04, albedo,
// metallic) (exact for metallic = 1, where albedo = F0; clamped to [0, 1]
// otherwise; white for metallic = 0, where the model fixes F0 = 0.04 and
// ignores the argument). edgeTint stays white (1, 1, 1).
glm::dvec3 directionalAlbedo(double NoV, double roughness, glm::dvec3 F0, double metallic,
                             const ShadingModel& model, int samples);

}  // namespace rl::ref
