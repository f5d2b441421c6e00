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

namespace rl::ref {

// A ray/sphere hit.
struct Hit {
    double t = kNoHit;      // distance along the unit ray direction; kNoHit for a miss
    glm::dvec3 p{0.0};      // hit point, world space
    glm::dvec3 n{0.0};      // unit normal (p - centre)/radius, flipped to face the incoming ray
    double magnitude = 0;   // max(maxAbs(p), maxAbs(centre) + radius): the scale of the numbers behind p
    int sphere = -1;        // index into Scene::spheres
};

// ---- visibility ------------------------------------------------------------------

// Nearest sphere hit with t > 0 along the unit direction dir. Fills `out` and
// returns true, or returns false (and leaves `out` alone) on a miss.
bool closestHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, Hit& out);

// True when some sphere is hit at 0 < t < tMax along the unit direction dir.
// Stops at the first occluder: a shadow ray needs whether, not where.
bool anyHitBefore(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir, double tMax);

// Exercise 04's lightVisibility(): true when nothing lies between the hit and
// the light. The shadow ray starts at offsetRayOrigin(p, n, magnitude) and
// the light is occluded iff a sphere is hit closer than the light from there.
bool lightVisible(const Scene& scene, const Hit& hit, glm::dvec3 lightPosition);

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
// and the ray continues from offsetRayOrigin(p, n, magnitude) in reflect(d, n).
// A ray that hits nothing adds throughput * background and stops.
// The bounce Fresnel is F_SchlickRoughness for EVERY model variant: the
// variants (scene.model) change the direct-light BRDF only.
glm::dvec3 traceRadiance(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir);

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

// Renders the scene at render.width x render.height: averaged linear radiance
// (as float) and its display step in double, quantised by rl::quantize8.
// Pixel (i, j) (j from the bottom) lands in image row height - 1 - j (row 0 = top).
// Rows are shared among `threads` worker threads (0: hardware_concurrency());
// the result does not depend on the thread count.
// Throws rl::Error for a non-positive size or spp, or a degenerate camera.
Rendering renderCpu(const Scene& scene, int threads = 0);

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
