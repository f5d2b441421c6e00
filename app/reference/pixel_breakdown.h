// "Ask a pixel" (raylab view): everything the CPU reference computes for
// the ray through one pixel's centre, term by term, in double: the hit, its
// material, p, n, v, each light's l, h, NoL, NoH, D, G, F, its diffuse and
// specular radiance and whether it is shadowed, and the bounce chain with
// its throughputs. Built only from the public functions of
// brdf_reference.h and cpu_reference.h, in the order traceRadiance()
// applies them, so the sum of the chain IS the reference radiance (a test
// holds them equal).
#pragma once

#include "core/scene.h"
#include "reference/sh9.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rl::ref {

struct LightTerms {
    int light = 0;  // index into Scene::lights
    glm::dvec3 l{0.0}, h{0.0};
    double distance = 0;  // |light - p|
    double NoL = 0, NoH = 0, VoH = 0;
    double D = 0, G = 0;  // the scene's model variant (GGX / Beckmann; Schlick-GGX / Smith)
    glm::dvec3 F{0.0};    // the scene's Fresnel variant at VoH
    glm::dvec3 E{0.0};    // irradiance C I NoL / d^2
    bool facesAway = false;  // NoL = 0: no light, no shadow ray
    bool shadowed = false;   // the shadow ray hits a sphere before the light
    glm::dvec3 diffuse{0.0}, specular{0.0};  // f_d E and f_s E (0 when shadowed or facing away)
};

// The GL picture's approximation of environment light (shaders/environment.glsl,
// exercise 11) needs the host's tables (render/environment_resources.h builds
// them; this layer only reads them): the nine SH coefficients, the
// prefiltered chain and the split-sum table, all in the image's frame and
// without intensity.
struct EnvironmentTables {
    const Sh9* sh = nullptr;
    const std::vector<RadianceImage>* levels = nullptr;  // level k for roughness k / (levels - 1)
    const std::vector<glm::dvec2>* table = nullptr;      // [j * tableSize + i]: (scale, bias)
    int tableSize = 0;
    // The map's sun (render/environment_caps.h, findSun; its power above the
    // sky around it), which the debugger's irradiance adds to SH9's as a
    // point source (environment.glsl, sunIrradianceCorrection; the picture
    // adds it as a light of its own, sunLight): image frame, no intensity.
    bool sunPresent = false;
    glm::dvec3 sunDirection{0.0, 1.0, 0.0};
    glm::dvec3 sunPower{0.0};
    double sunAngularRadius = 0.0;
};

// The approximation's terms at one hit, in double, as environmentHitLight()
// computes them in float32 on the same tables: what exercise 11's functions
// should give there. Not the Monte Carlo truth (environment_reference.h):
// the debugger asks whether the code computes the model's approximation.
struct EnvironmentTerms {
    glm::dvec3 irradiance{0.0};   // intensity * sh9Irradiance(sh, local n): shIrradiance
    double level = 0;             // clamp(roughness, 0, 1) * (levels - 1): prefilteredLevel
    glm::dvec3 prefiltered{0.0};  // intensity * the chain at local reflect(-v, n), that level, bilinear
    // How much `prefiltered` moves per channel when reflect(-v, n) turns by
    // kLookupAngle: the float direction and the shader's atan and acos miss
    // the double one by up to ~1e-5 rad, times the map's gradient there (a
    // small bright sun makes it steep: 1.4e-3 relative on sky-spheres). The debugger adds
    // it to the tolerance of the lookup and of the values made from it.
    glm::dvec3 prefilteredSpread{0.0};
    glm::dvec2 scaleBias{0.0};    // the split-sum table at (clamped n.v, roughness), bilinear
    // Exercise 12: the form factors of the other spheres at the hit, summed
    // (reference/sphere_form_factor.h): the share of the sky's diffuse light
    // they hide, before the occlusion's framework parts (docs/model.md).
    double formFactors = 0.0;
    glm::dvec3 light{0.0};        // environmentShading(max(irradiance + the sun's correction, 0), prefiltered, scaleBias, m), before occlusion
    // What the picture's environmentHitLight() adds before occlusion: exercise
    // 11's shading of SH9's irradiance with the sun's three bands taken out,
    // plus the sun as a light of its own through the scene's BRDF (sunLight,
    // shaders/environment.glsl; docs/model.md "The sun").
    glm::dvec3 pictureLight{0.0};
};
constexpr double kLookupAngle = 1e-4;  // radians: the shader's float atan and acos (a GPU's approximations), with room
EnvironmentTerms environmentTerms(const Environment& environment, const EnvironmentTables& tables, glm::dvec3 n,
                                  glm::dvec3 v, const Material& m, const ShadingModel& model);

struct BounceTerms {
    int depth = 0;  // 0 = the primary hit
    glm::dvec3 origin{0.0}, dir{0.0};
    bool hit = false;  // false: the ray leaves the scene (background)
    int sphere = -1;
    glm::dvec3 p{0.0}, n{0.0}, v{0.0};
    double t = 0, NoV = 0;  // NoV clamped to [1e-4, 1] as the bounce's Fresnel uses it
    Material material;
    std::vector<LightTerms> lights;
    glm::dvec3 ambient{0.0};          // ambient * albedo * ao
    std::optional<EnvironmentTerms> environment;  // with an environment and its tables (explainPixel)
    glm::dvec3 shaded{0.0};           // direct light of every light + ambient: shadeHit() (+ environment->light)
    glm::dvec3 throughput{1.0};       // before this hit
    glm::dvec3 contribution{0.0};     // throughput * shaded (or * background on a miss)
    glm::dvec3 Fr{0.0};               // F_SchlickRoughness(F0, NoV, r): the next throughput factor
};

struct PixelTerms {
    int i = 0, j = 0;  // column from the left, row from the BOTTOM (the reference's convention)
    int height = 0;    // of the picture: the text names the row from the top (height - 1 - j), as every command does
    std::vector<BounceTerms> chain;  // the primary hit, then the bounces, up to the first miss
    glm::dvec3 radiance{0.0};        // sum of the contributions: traceRadiance of the centre ray
    glm::dvec3 pixelRadiance{0.0};   // the reference's pixel (all spp samples)
    glm::dvec3 display{0.0};         // displayEncode(pixelRadiance)
};

// The ray through the centre of pixel (i, j) of a width x height picture
// seen by `camera` (the live view's; its fov is used). Throws rl::Error for
// a pixel outside the picture. With `environment` (tables of the scene's
// environment), each hit adds the approximation's environment light
// (BounceTerms::environment) and a camera ray that misses sees the
// environment, a bounce that escapes nothing, as the GL picture: the chain's
// radiance is then the GL picture's model, not traceRadiance's Monte Carlo
// integral (pixelRadiance stays the reference's).
PixelTerms explainPixel(const Scene& scene, const Camera& camera, int width, int height, int i, int j,
                        const EnvironmentTables* environment = nullptr);

// The terminal's (and the panel's) text, one fact a line, 6 significant digits.
std::string formatPixelTerms(const Scene& scene, const PixelTerms& terms);

}  // namespace rl::ref
