// brdf_reference.h: the reference model of docs/model.md,
// term by term, in double precision. It is written independently of the GLSL
// (no shared code), so that the shader and the exercise probes can be checked
// against it. Every function here is pure and thread-safe.
//
// Notation, as in the spec: n the unit normal, v the unit direction towards
// the viewer, l the unit direction towards the light, h = normalize(l + v),
// NoV = n.v, NoL = n.l, NoH = n.h, VoH = v.h (= l.h), r the clamped perceptual
// roughness, alpha = r^2.
//
// Colour spaces: albedo, F0, radiance and irradiance are LINEAR; only the
// results of encodeGamma() and displayEncode() are display-encoded.
//
// The file reads in the order of the exercises (01 camera ... 10 display);
// the model variants of the accuracy issue (Beckmann, exact Smith, exact
// Fresnel, Burley, Blinn-Phong) sit beside the term they replace.
#pragma once

#include "core/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rl::ref {

constexpr double kPi = 3.14159265358979323846;

// intersectSphere() returns kNoHit when the ray misses (as the GLSL NO_HIT).
constexpr double kNoHit = -1.0;

// Secondary rays start this far along the normal, relative to hit magnitude.
constexpr double kRayOffsetRelative = 1.0 / 524288.0;  // 2^-19: 16 float32 ulps of the largest number that produced p

// The spec's clamps, shared by every term below.
// The least perceptual roughness: r >= 0.045 keeps alpha^2 = 4.1e-6 > 0, so D
// stays finite at NoH = 1. The C++'s one definition (the GLSL's:
// MIN_ROUGHNESS in shaders/common.glsl; tests/unit holds them equal).
constexpr double kMinRoughness = 0.045;
constexpr double kMinNoV = 1e-4;         // spec: NoV >= 1e-4 keeps 1/(4 NoL NoV) finite at grazing view

// ---- 01 camera ---------------------------------------------------------------

// Offset of sample s (0 <= s < n*n) inside its pixel: the centre of cell
// (a, b) of an n x n grid, a = s % n along x, b = s / n along y:
//     ((a + 0.5)/n, (b + 0.5)/n);  (0.5, 0.5) for n = 1.
glm::dvec2 sampleOffset(int s, int n);

// Unit direction of the camera ray through pixelSample = (i + sx, j + sy),
// j counted from the BOTTOM row (spec, "Camera"):
//     t = tan(fovY/2), aspect = width/height
//     x = (2 (i + sx)/width - 1) t aspect,  y = (2 (j + sy)/height - 1) t
//     d = normalize(x right + y up + forward)
glm::dvec3 cameraRayDirection(glm::dvec2 pixelSample, glm::dvec2 resolution, double fovYRadians,
                              glm::dvec3 right, glm::dvec3 up, glm::dvec3 forward);

// ---- 02 ray/sphere -------------------------------------------------------------

// Nearest t > 0 where origin + t unitDir meets the sphere, or kNoHit.
// unitDir MUST have unit length (the quadratic below assumes |d| = 1).
// Numerically stable form, Haines et al. 2019, "Precision Improvements for
// Ray/Sphere Intersection", Ray Tracing Gems ch. 7:
//     f = origin - center, b = f.d, disc = r^2 - |f - b d|^2, c = |f|^2 - r^2
//     q = -b - sign(b) sqrt(disc), roots c/q and q; the smallest positive one.
double intersectSphere(glm::dvec3 origin, glm::dvec3 unitDir, glm::dvec3 center, double radius);

// ---- 03 Lambert and point lights ----------------------------------------------

// Lambert 1760: a perfectly matte surface, f = albedo / pi.
glm::dvec3 Fd_Lambert(glm::dvec3 albedo);

// Irradiance at p (unit normal n) from a point light of intensity C I:
//     d2 = |c - p|^2, l = (c - p)/sqrt(d2), E = (C I / d2) clamp(n.l, 0, 1)
// Zero when d2 <= 1e-12 (spec) or when the light is behind the surface.
glm::dvec3 pointLightIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 lightPosition,
                                glm::dvec3 lightIntensity);

// ---- 04 shadow rays ------------------------------------------------------------

// Origin of a secondary ray leaving the hit point p along its normal n:
//     p + n (kRayOffsetRelative magnitude)
// magnitude = max(maxAbs(p), maxAbs(center) + radius) of the sphere hit: the
// size of the numbers behind p, so the offset scales with the scene.
glm::dvec3 offsetRayOrigin(glm::dvec3 p, glm::dvec3 n, double magnitude);

// ---- 05 normal distribution D --------------------------------------------------

// GGX / Trowbridge-Reitz, Walter et al. 2007 eq. 33:
//     D = alpha^2 / (pi ((NoH)^2 (alpha^2 - 1) + 1)^2)
// evaluated as alpha^2 / (pi (|n x h|^2 + NoH^2 alpha^2)^2), the same value
// without the cancellation of 1 - NoH^2 near the peak.
double D_GGX(glm::dvec3 n, glm::dvec3 h, double alpha);

// Variant. Beckmann 1963, as in Walter et al. 2007 eq. 25 (and Cook-Torrance 1982):
//     D = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 NoH^4),  tan^2 = |n x h|^2 / NoH^2
// Zero for NoH <= 0.
double D_Beckmann(glm::dvec3 n, glm::dvec3 h, double alpha);

// ---- 06 geometry (masking-shadowing) G -----------------------------------------

// Schlick-GGX masking of one direction, Karis 2013, "Real Shading in Unreal
// Engine 4":  G1(x) = x / (x (1 - k) + k),  x = NoV or NoL.
double G1_SchlickGGX(double NoX, double k);

// The reference G (spec): Smith's separable product of Schlick-GGX terms,
//     r = clamp(roughness, 0.045, 1), k = (r + 1)^2 / 8, G = G1(NoV) G1(NoL).
// Takes the perceptual roughness, NOT alpha.
double G_SchlickGGX(double NoV, double NoL, double roughness);

// Variant. Exact Smith masking of one direction for GGX, Walter et al. 2007
// eq. 34 (with the spec's erratum):  G1(x) = 2 x / (x + sqrt(alpha^2 + (1 - alpha^2) x^2)).
double G1_SmithGGX(double NoX, double alpha);

// Variant. Separable Smith G for GGX: G = G1_SmithGGX(NoV) G1_SmithGGX(NoL).
double G_SmithGGXSeparable(double NoV, double NoL, double alpha);

// Variant. Height-correlated Smith G for GGX, Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs", G2 = 1 / (1 + Lambda(v) + Lambda(l)):
//     G = 2 NoL NoV / (NoV sqrt(alpha^2 + (1 - alpha^2) NoL^2) + NoL sqrt(alpha^2 + (1 - alpha^2) NoV^2))
// This is G, NOT Filament's V_SmithGGXCorrelated = G / (4 NoL NoV).
double G_SmithGGXCorrelated(double NoV, double NoL, double alpha);

// ---- 07 Fresnel F ----------------------------------------------------------------

// The reference F. Schlick 1994, "An Inexpensive BRDF Model for
// Physically-based Rendering":  F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5.
glm::dvec3 F_Schlick(glm::dvec3 F0, double VoH);

// Variant. Exact unpolarised Fresnel of a dielectric, Walter et al. 2007 eq. 22,
// per channel with the index of refraction that gives F0 at normal incidence:
//     n = (1 + sqrt F0) / (1 - sqrt F0),  c = VoH,  g = sqrt(n^2 - 1 + c^2)
//     F = 1/2 (g - c)^2/(g + c)^2 (1 + ((c (g + c) - 1) / (c (g - c) + 1))^2)
glm::dvec3 F_Dielectric(glm::dvec3 F0, double VoH);

// Variant. Exact unpolarised Fresnel of a conductor (complex index n + i k),
// with (n, k) from Gulbrandsen 2014, "Artist Friendly Metallic Fresnel",
// reflectivity r = F0 and edge tint g = edgeTint:
//     n = g (1 - r)/(1 + r) + (1 - g)(1 + sqrt r)/(1 - sqrt r)
//     k = sqrt((r (n + 1)^2 - (n - 1)^2) / (1 - r))
// and the exact conductor equations (Gulbrandsen 2014; Pharr et al., PBR 3rd ed., sec. 8.2.1):
//     2a^2 = sqrt((n^2 - k^2 - s^2)^2 + 4 n^2 k^2) + (n^2 - k^2 - s^2),  s = sin(theta), c = VoH
//     Rs = (a^2 + b^2 - 2 a c + c^2) / (a^2 + b^2 + 2 a c + c^2)
//     Rp = Rs (c^2 (a^2 + b^2) - 2 a c s^2 + s^4) / (c^2 (a^2 + b^2) + 2 a c s^2 + s^4),  F = (Rs + Rp)/2
glm::dvec3 F_Conductor(glm::dvec3 F0, glm::dvec3 edgeTint, double VoH);

// ---- diffuse variant -------------------------------------------------------------

// Variant. Burley 2012, "Physically-Based Shading at Disney":
//     F90 = 0.5 + 2 alpha LoH^2
//     f = albedo/pi (1 + (F90 - 1)(1 - NoL)^5) (1 + (F90 - 1)(1 - NoV)^5)
// With alpha = r^2 as Filament does (Filament's Fd_Burley gets its
// `roughness` = alpha); Burley's course notes put the perceptual r there.
glm::dvec3 Fd_Burley(glm::dvec3 albedo, double NoV, double NoL, double LoH, double alpha);

// ---- Blinn-Phong variant (whole-model switch) -----------------------------------

// Shininess from GGX alpha, the usual match of the two lobes' peaks (Walter
// et al. 2007, Phong distribution):  s = 2 / alpha^2 - 2  (s = 0 at alpha = 1).
double shininessFromAlpha(double alpha);

// Blinn 1977 lobe with the exact energy normalisation of the cosine-weighted
// lobe at normal incidence (Giesen 2009, "Derivation of Phong and Blinn-Phong BRDF
// normalization factors"):
//     f = (s + 2)(s + 4) / (8 pi (2^(-s/2) + s)) NoH^s
// Not the popular (s + 8)/(8 pi): that one reflects up to 7% more than it
// receives for s > 4 (directional albedo (s^2 + 8s)/(s^2 + 6s + 8) at NoV = 1).
double Fr_BlinnPhong(double NoH, double shininess);

// The Blinn-Phong model, replacing the whole Cook-Torrance BRDF:
//     s = shininessFromAlpha(alpha), F0 = mix(0.04, albedo, metallic)
//     f = (1 - F0)(1 - metallic) albedo/pi + F0 Fr_BlinnPhong(NoH, s),  0 when NoL = 0
// No Fresnel angle dependence, no geometry term, Lambert diffuse always.
glm::dvec3 blinnPhongBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m);

// ---- 08 Cook-Torrance, metallic workflow -------------------------------------------

// Perceptual roughness as used for shading: clamp(roughness, 0.045, 1).
double clampRoughness(double roughness);

// GGX alpha from perceptual roughness: r = clamp(roughness, 0.045, 1), alpha = r^2.
double ggxAlpha(double roughness);

// Reflectance at normal incidence: F0 = mix(vec3(0.04), albedo, metallic).
glm::dvec3 baseReflectance(const Material& m);

// Specular lobe D G F / (4 NoL NoV), NoV = clamp(n.v, 1e-4, 1), NoL = clamp(n.l, 0, 1);
// 0 when NoL = 0.
glm::dvec3 specularBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m);

// Diffuse lobe kd albedo/pi, kd = (1 - F_Schlick(F0, VoH))(1 - metallic).
// Like the GLSL diffuseBRDF(), it does not look at NoL.
glm::dvec3 diffuseBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m);

// The reference BRDF f(l, v) = diffuseBRDF + specularBRDF (linear, per
// steradian), 0 when NoL = 0.
glm::dvec3 cookTorranceBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m);

// The same three with the model variants of `model` (scene.h). With the
// default ShadingModel they return exactly the reference values above.
//   distribution: D_GGX | D_Beckmann (alpha)
//   geometry:     G_SchlickGGX (r) | G_SmithGGXSeparable | G_SmithGGXCorrelated (alpha)
//   fresnel:      F_Schlick | F_Dielectric | F_Conductor (F0, m.edgeTint), used in the
//                 specular lobe AND in kd = (1 - F)(1 - metallic)
//   diffuse:      Fd_Lambert | Fd_Burley (alpha), times kd
//   blinnPhong:   blinnPhongBRDF() for the whole BRDF (the other switches are ignored)
glm::dvec3 specularBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m, const ShadingModel& model);
glm::dvec3 diffuseBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m, const ShadingModel& model);
glm::dvec3 cookTorranceBRDF(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, const Material& m, const ShadingModel& model);

// ---- 09 reflections ------------------------------------------------------------------

// Roughness-aware Schlick Fresnel of the macro normal, for the mirror bounces
// (Lagarde 2011, "Adopting a physically based shading model"; spec "Reflection bounces"):
//     Fr = F0 + (max(vec3(1 - r), F0) - F0)(1 - clamp(NoV, 0, 1))^5,  r = clamp(roughness, 0.045, 1)
// Every model variant bounces with this one (the variants change direct light only).
glm::dvec3 F_SchlickRoughness(glm::dvec3 F0, double NoV, double roughness);

// ---- 10 display ------------------------------------------------------------------------

// Tone mapping of exposed linear radiance c >= 0 into [0, 1]:
//     Reinhard: c/(1 + c);  Exponential: 1 - exp(-c);  None: clamp(c, 0, 1)
glm::dvec3 toneMap(glm::dvec3 c, ToneMap op);

// Display encoding of a tone-mapped value c in [0, 1]: c^(1/gamma), or, when
// srgb, the exact sRGB transfer function (IEC 61966-2-1):
//     c <= 0.0031308 ? 12.92 c : 1.055 c^(1/2.4) - 0.055
glm::dvec3 encodeGamma(glm::dvec3 c, double gamma, bool srgb);

// The display step: exposure, tone map, gamma, then clamp to [0, 1].
// Linear radiance in, display-encoded value out (8-bit: rl::quantize8).
glm::dvec3 displayEncode(glm::dvec3 radiance, const RenderSettings& settings);

}  // namespace rl::ref
