// brdf_reference.cpp: the terms of the reference model in double precision.
// Formulas and sources are in brdf_reference.h; comments here explain only
// the numerical choices.
#include "reference/brdf_reference.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::ref {

using glm::dvec2;
using glm::dvec3;

namespace {

double pow5(double x) {
    double x2 = x * x;
    return x2 * x2 * x;
}

double saturate(double x) { return std::clamp(x, 0.0, 1.0); }

// Largest reflectance that the exact Fresnel variants invert into an index of
// refraction: at F0 = 1 both inversions divide by 1 - sqrt(F0) = 0. 1 - 1e-9
// reflects the same as F0 = 1 in 8 bits and in float (whose ulp at 1 is 6e-8),
// and gives n, k <= 4e9: their squares stay far inside double's range.
constexpr double kMaxInvertibleF0 = 1.0 - 1e-9;

}  // namespace

// ---- 01 camera ---------------------------------------------------------------

dvec2 sampleOffset(int s, int n) {
    int a = s % n;
    int b = s / n;
    return (dvec2(a, b) + 0.5) / double(n);
}

dvec3 cameraRayDirection(dvec2 pixelSample, dvec2 resolution, double fovYRadians, dvec3 right, dvec3 up,
                         dvec3 forward) {
    double t = std::tan(0.5 * fovYRadians);
    double aspect = resolution.x / resolution.y;
    dvec2 ndc = 2.0 * pixelSample / resolution - 1.0;  // (-1, 1) across the image
    double x = ndc.x * t * aspect;
    double y = ndc.y * t;
    return glm::normalize(x * right + y * up + forward);
}

// ---- 02 ray/sphere -------------------------------------------------------------

double intersectSphere(dvec3 origin, dvec3 unitDir, dvec3 center, double radius) {
    dvec3 f = origin - center;
    double b = glm::dot(f, unitDir);
    dvec3 perpendicular = f - b * unitDir;  // from the centre to the ray's closest point
    double discriminant = radius * radius - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0.0) return kNoHit;
    double c = glm::dot(f, f) - radius * radius;
    // sign(b) taken as +1 at b = 0 (glm::sign would give 0 and lose a root).
    double q = -b - (b >= 0.0 ? 1.0 : -1.0) * std::sqrt(discriminant);
    if (q == 0.0) return kNoHit;  // origin on the surface, ray tangent: both roots are 0
    double t0 = c / q;
    double t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0) return t0;  // the near root, in front of the origin
    if (t1 > 0.0) return t1;  // origin inside the sphere: the far root
    return kNoHit;            // the sphere lies behind the origin
}

// ---- 03 Lambert and point lights ----------------------------------------------

dvec3 Fd_Lambert(dvec3 albedo) { return albedo / kPi; }

dvec3 pointLightIrradiance(dvec3 p, dvec3 n, dvec3 lightPosition, dvec3 lightIntensity) {
    dvec3 toLight = lightPosition - p;
    double d2 = glm::dot(toLight, toLight);
    if (d2 <= 1e-12) return dvec3(0.0);  // spec: a light (almost) at p has no direction and 1/d2 explodes
    double NoL = saturate(glm::dot(n, toLight / std::sqrt(d2)));
    return lightIntensity / d2 * NoL;
}

// ---- 04 shadow rays ------------------------------------------------------------

dvec3 offsetRayOrigin(dvec3 p, dvec3 n, double magnitude) {
    return p + n * (kRayOffsetRelative * magnitude);
}

// ---- 05 normal distribution D --------------------------------------------------

double D_GGX(dvec3 n, dvec3 h, double alpha) {
    double NoH = glm::dot(n, h);
    dvec3 NxH = glm::cross(n, h);
    double a2 = alpha * alpha;
    double denom = glm::dot(NxH, NxH) + NoH * NoH * a2;  // = NoH^2 (alpha^2 - 1) + 1 for unit n, h
    return a2 / (kPi * denom * denom);
}

double D_Beckmann(dvec3 n, dvec3 h, double alpha) {
    double NoH = glm::dot(n, h);
    if (NoH <= 0.0) return 0.0;  // back-facing microfacet normal: no such facets
    dvec3 NxH = glm::cross(n, h);
    double NoH2 = NoH * NoH;
    double a2 = alpha * alpha;
    double tan2 = glm::dot(NxH, NxH) / NoH2;
    return std::exp(-tan2 / a2) / (kPi * a2 * NoH2 * NoH2);
}

// ---- 06 geometry G ---------------------------------------------------------------

double G1_SchlickGGX(double NoX, double k) { return NoX / (NoX * (1.0 - k) + k); }

double G_SchlickGGX(double NoV, double NoL, double roughness) {
    double r = clampRoughness(roughness);
    double k = (r + 1.0) * (r + 1.0) / 8.0;
    return G1_SchlickGGX(NoV, k) * G1_SchlickGGX(NoL, k);
}

double G1_SmithGGX(double NoX, double alpha) {
    double a2 = alpha * alpha;
    return 2.0 * NoX / (NoX + std::sqrt(a2 + (1.0 - a2) * NoX * NoX));
}

double G_SmithGGXSeparable(double NoV, double NoL, double alpha) {
    return G1_SmithGGX(NoV, alpha) * G1_SmithGGX(NoL, alpha);
}

double G_SmithGGXCorrelated(double NoV, double NoL, double alpha) {
    double a2 = alpha * alpha;
    double lambdaV = NoL * std::sqrt(a2 + (1.0 - a2) * NoV * NoV);
    double lambdaL = NoV * std::sqrt(a2 + (1.0 - a2) * NoL * NoL);
    return 2.0 * NoL * NoV / (lambdaV + lambdaL);
}

// ---- 07 Fresnel F ----------------------------------------------------------------

dvec3 F_Schlick(dvec3 F0, double VoH) {
    double m = pow5(1.0 - saturate(VoH));
    return F0 + (1.0 - F0) * m;
}

namespace {

double fresnelDielectric(double F0, double c) {
    double sqrtF0 = std::sqrt(std::clamp(F0, 0.0, kMaxInvertibleF0));
    double n = (1.0 + sqrtF0) / (1.0 - sqrtF0);
    if (n <= 1.0) return 0.0;  // F0 = 0: equal indices, no interface, nothing reflects
    double g = std::sqrt(n * n - 1.0 + c * c);  // > 0 since n > 1: no total internal reflection from outside
    double ratio = (g - c) / (g + c);
    double tail = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * ratio * ratio * (1.0 + tail * tail);
}

double fresnelConductor(double F0, double edgeTint, double c) {
    double r = std::clamp(F0, 0.0, kMaxInvertibleF0);
    double g = std::clamp(edgeTint, 0.0, 1.0);  // Gulbrandsen's g is defined on [0, 1]
    double sqrtR = std::sqrt(r);
    double n = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + sqrtR) / (1.0 - sqrtR);
    // r (n+1)^2 - (n-1)^2 rearranged to (r - 1)(n^2 + 1) + 2 n (r + 1): no
    // cancellation of two ~n^2 terms when r is close to 1. Clamped at 0 so
    // that rounding cannot make k imaginary.
    double k2 = std::max(0.0, ((r - 1.0) * (n * n + 1.0) + 2.0 * n * (r + 1.0)) / (1.0 - r));

    double cos2 = c * c;
    double sin2 = 1.0 - cos2;
    double t0 = n * n - k2 - sin2;
    double a2PlusB2 = std::sqrt(t0 * t0 + 4.0 * n * n * k2);
    double a = std::sqrt(std::max(0.0, 0.5 * (a2PlusB2 + t0)));  // max: a2PlusB2 >= |t0| up to rounding
    double t1 = a2PlusB2 + cos2;
    double t2 = 2.0 * c * a;
    double Rs = (t1 - t2) / (t1 + t2);
    double t3 = cos2 * a2PlusB2 + sin2 * sin2;
    double t4 = t2 * sin2;
    double Rp = Rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (Rs + Rp);
}

}  // namespace

dvec3 F_Dielectric(dvec3 F0, double VoH) {
    double c = saturate(VoH);
    return dvec3(fresnelDielectric(F0.x, c), fresnelDielectric(F0.y, c), fresnelDielectric(F0.z, c));
}

dvec3 F_Conductor(dvec3 F0, dvec3 edgeTint, double VoH) {
    double c = saturate(VoH);
    return dvec3(fresnelConductor(F0.x, edgeTint.x, c), fresnelConductor(F0.y, edgeTint.y, c),
                 fresnelConductor(F0.z, edgeTint.z, c));
}

// ---- diffuse variant -------------------------------------------------------------

dvec3 Fd_Burley(dvec3 albedo, double NoV, double NoL, double LoH, double alpha) {
    double F90 = 0.5 + 2.0 * alpha * LoH * LoH;
    double lightScatter = 1.0 + (F90 - 1.0) * pow5(1.0 - NoL);
    double viewScatter = 1.0 + (F90 - 1.0) * pow5(1.0 - NoV);
    return albedo / kPi * (lightScatter * viewScatter);
}

// ---- Blinn-Phong variant ---------------------------------------------------------

double shininessFromAlpha(double alpha) { return 2.0 / (alpha * alpha) - 2.0; }

double Fr_BlinnPhong(double NoH, double shininess) {
    double s = shininess;
    double normalization = (s + 2.0) * (s + 4.0) / (8.0 * kPi * (std::exp2(-0.5 * s) + s));
    return normalization * std::pow(std::max(NoH, 0.0), s);
}

namespace {

// The two lobes of blinnPhongBRDF(), for the variant-aware specularBRDF() and diffuseBRDF().
dvec3 blinnPhongSpecular(dvec3 n, dvec3 v, dvec3 l, const Material& m) {
    dvec3 h = glm::normalize(l + v);
    return baseReflectance(m) * Fr_BlinnPhong(glm::dot(n, h), shininessFromAlpha(ggxAlpha(m.roughness)));
}

dvec3 blinnPhongDiffuse(const Material& m) {
    return (1.0 - baseReflectance(m)) * (1.0 - m.metallic) * Fd_Lambert(m.albedo);
}

}  // namespace

dvec3 blinnPhongBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m) {
    if (saturate(glm::dot(n, l)) == 0.0) return dvec3(0.0);  // light at or below the horizon
    return blinnPhongDiffuse(m) + blinnPhongSpecular(n, v, l, m);
}

// ---- 08 Cook-Torrance ------------------------------------------------------------

double clampRoughness(double roughness) { return std::clamp(roughness, kMinRoughness, 1.0); }

double ggxAlpha(double roughness) {
    double r = clampRoughness(roughness);
    return r * r;
}

dvec3 baseReflectance(const Material& m) { return glm::mix(dvec3(0.04), m.albedo, m.metallic); }

dvec3 specularBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m) {
    return specularBRDF(n, v, l, m, ShadingModel{});
}

dvec3 diffuseBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m) {
    return diffuseBRDF(n, v, l, m, ShadingModel{});
}

dvec3 cookTorranceBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m) {
    return cookTorranceBRDF(n, v, l, m, ShadingModel{});
}

namespace {

// The Fresnel term of the chosen variant, at the angle VoH between v and h.
dvec3 fresnel(const Material& m, const ShadingModel& model, double VoH) {
    dvec3 F0 = baseReflectance(m);
    switch (model.fresnel) {
        case FresnelModel::Dielectric: return F_Dielectric(F0, VoH);
        case FresnelModel::Conductor: return F_Conductor(F0, m.edgeTint, VoH);
        case FresnelModel::Schlick: break;
    }
    return F_Schlick(F0, VoH);
}

}  // namespace

dvec3 specularBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m, const ShadingModel& model) {
    double NoL = saturate(glm::dot(n, l));
    if (NoL == 0.0) return dvec3(0.0);
    if (model.blinnPhong) return blinnPhongSpecular(n, v, l, m);
    double NoV = std::clamp(glm::dot(n, v), kMinNoV, 1.0);
    dvec3 h = glm::normalize(l + v);
    double alpha = ggxAlpha(m.roughness);

    double D = model.distribution == DistributionModel::Beckmann ? D_Beckmann(n, h, alpha) : D_GGX(n, h, alpha);
    double G = 0.0;
    switch (model.geometry) {
        case GeometryModel::SchlickGGX: G = G_SchlickGGX(NoV, NoL, m.roughness); break;
        case GeometryModel::SmithGGXSeparable: G = G_SmithGGXSeparable(NoV, NoL, alpha); break;
        case GeometryModel::SmithGGXCorrelated: G = G_SmithGGXCorrelated(NoV, NoL, alpha); break;
    }
    dvec3 F = fresnel(m, model, glm::dot(h, v));
    return D * G * F / (4.0 * NoL * NoV);
}

dvec3 diffuseBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m, const ShadingModel& model) {
    if (model.blinnPhong) return blinnPhongDiffuse(m);
    dvec3 h = glm::normalize(l + v);
    double VoH = glm::dot(v, h);
    dvec3 kd = (1.0 - fresnel(m, model, VoH)) * (1.0 - m.metallic);
    if (model.diffuse == DiffuseModel::Burley) {
        double NoV = std::clamp(glm::dot(n, v), kMinNoV, 1.0);
        double NoL = saturate(glm::dot(n, l));
        return kd * Fd_Burley(m.albedo, NoV, NoL, VoH, ggxAlpha(m.roughness));  // LoH = VoH
    }
    return kd * Fd_Lambert(m.albedo);
}

dvec3 cookTorranceBRDF(dvec3 n, dvec3 v, dvec3 l, const Material& m, const ShadingModel& model) {
    if (saturate(glm::dot(n, l)) == 0.0) return dvec3(0.0);  // light at or below the horizon
    return diffuseBRDF(n, v, l, m, model) + specularBRDF(n, v, l, m, model);
}

// ---- 09 reflections ------------------------------------------------------------------

dvec3 F_SchlickRoughness(dvec3 F0, double NoV, double roughness) {
    double r = clampRoughness(roughness);
    double m = pow5(1.0 - saturate(NoV));
    return F0 + (glm::max(dvec3(1.0 - r), F0) - F0) * m;
}

// ---- 10 display ------------------------------------------------------------------------

dvec3 toneMap(dvec3 c, ToneMap op) {
    switch (op) {
        case ToneMap::Reinhard: return c / (1.0 + c);
        case ToneMap::Exponential: return 1.0 - glm::exp(-c);
        case ToneMap::None: break;
    }
    return glm::clamp(c, 0.0, 1.0);
}

namespace {

double srgbEncode(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;  // IEC 61966-2-1 constants
}

}  // namespace

dvec3 encodeGamma(dvec3 c, double gamma, bool srgb) {
    // Tone-mapped values are >= 0; max(., 0) only keeps pow() defined (no NaN)
    // should a negative value slip in.
    c = glm::max(c, dvec3(0.0));
    if (srgb) return dvec3(srgbEncode(c.x), srgbEncode(c.y), srgbEncode(c.z));
    return glm::pow(c, dvec3(1.0 / gamma));
}

dvec3 displayEncode(dvec3 radiance, const RenderSettings& settings) {
    dvec3 c = toneMap(radiance * settings.exposure, settings.tonemap);
    return glm::clamp(encodeGamma(c, settings.gamma, settings.srgb), 0.0, 1.0);
}

}  // namespace rl::ref
