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

#include <glm/vec3.hpp>

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
    glm::dvec3 shaded{0.0};           // direct light of every light + ambient: shadeHit()
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
// a pixel outside the picture.
PixelTerms explainPixel(const Scene& scene, const Camera& camera, int width, int height, int i, int j);

// The terminal's (and the panel's) text, one fact a line, 6 significant digits.
std::string formatPixelTerms(const Scene& scene, const PixelTerms& terms);

}  // namespace rl::ref
