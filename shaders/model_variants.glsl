// model_variants.glsl: the shading-model variants a scene may ask for with
// its "model" object (docs/model-variants.md): Beckmann D, exact Smith G,
// exact Fresnel, Burley diffuse, Blinn-Phong. Compiled in only for such a
// scene: app/render/define_table.cpp then defines RL_MODEL_VARIANTS and one
// define per switch, and raytracer.glsl includes this file; the reference
// model never sees it. Framework code, not an exercise: the terms a variant
// keeps come from the exercises (D_GGX, G_SchlickGGX, F_Schlick, Fd_Lambert,
// ggxAlpha, baseReflectance), so every formula lives in one place.
//
// Formula for formula the same as the double-precision CPU reference
// (app/reference/brdf_reference.h); where float32 needs another arrangement
// of the same value, the comment says so (docs/numerics.md has the numbers).
// Notation: NoV = n.v, NoL = n.l, NoH = n.h, VoH = v.h (= l.h), r the clamped
// perceptual roughness, alpha = r^2. Colours are LINEAR.
//
//   define                  replaces                 with
//   RL_D_BECKMANN           D_GGX                    D_Beckmann
//   RL_G_SMITH_SEPARABLE    G_SchlickGGX             G_SmithGGXSeparable
//   RL_G_SMITH_CORRELATED   G_SchlickGGX             G_SmithGGXCorrelated
//   RL_F_DIELECTRIC         F_Schlick                F_Dielectric
//   RL_F_CONDUCTOR          F_Schlick                F_Conductor (uses the sphere's edge tint)
//   RL_FD_BURLEY            Fd_Lambert               Fd_Burley
//   RL_BLINN_PHONG          the whole BRDF           blinnPhong lobes (other switches ignored)
// The mirror bounces keep F_SchlickRoughness for every variant (exercise 09).

// The exact Fresnel terms invert F0 into an index of refraction, infinite at
// F0 = 1: they use 1 - F0 >= MIN_ONE_MINUS_F0 (F0 = 1 is the only float it
// changes: the largest float below 1 is 1 - 6e-8). 1e-8 gives n <= 4e8, so
// the conductor's largest intermediate, t0^2 + 4 n^2 k^2 <= 4 n^4 = 1e35, stays
// far below float's 3.4e38. The CPU reference clamps at 1e-9 (n = 4e9 in
// double); at F0 = 1 the two differ by about 2 / (n VoH): below 1e-6 for
// VoH > 5e-3, below 1e-3 for VoH > 5e-6.
const float MIN_ONE_MINUS_F0 = 1e-8;

// The conductor edge tint of sphere i (Gulbrandsen's g, linear rgb in [0, 1]).
vec3 sphereEdgeTint(int i) {
#ifdef RL_SPHERE_EDGE_TINT
    return RL_SPHERE_EDGE_TINT(i);
#else
    return u_sphereEdgeTint[i].rgb;
#endif
}

// x^5 (a name no exercise file uses: students' helpers must not collide).
float fifthPower(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

// ---- normal distribution D ----------------------------------------------------------

float D_Beckmann(vec3 n, vec3 h, float alpha) {
    // Beckmann 1963, as in Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 25:
    //     D = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 NoH^4),  tan^2 = |n x h|^2 / NoH^2,  0 for NoH <= 0
    // |n x h|^2, not 1 - NoH^2: near the peak the subtraction cancels in float32 (as in D_GGX).
    float NoH = dot(n, h);
    if (NoH <= 0.0) return 0.0;  // back-facing microfacet normal: no such facets
    vec3 NxH = cross(n, h);
    float NoH2 = NoH * NoH;
    float a2 = alpha * alpha;
    float tan2 = dot(NxH, NxH) / NoH2;
    return exp(-tan2 / a2) / (PI * a2 * NoH2 * NoH2);
}

// ---- geometry (masking-shadowing) G ---------------------------------------------------

float G1_SmithGGX(float NoX, float alpha) {
    // Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 34 (spec erratum applied):
    //     G1(x) = 2 x / (x + sqrt(alpha^2 + (1 - alpha^2) x^2)),  x = NoV or NoL
    float a2 = alpha * alpha;
    return 2.0 * NoX / (NoX + sqrt(a2 + (1.0 - a2) * NoX * NoX));
}

float G_SmithGGXSeparable(float NoV, float NoL, float alpha) {
    // Smith 1967, "Geometrical shadowing of a random rough surface", separable form with Walter's G1:
    //     G = G1_SmithGGX(NoV) G1_SmithGGX(NoL)
    return G1_SmithGGX(NoV, alpha) * G1_SmithGGX(NoL, alpha);
}

float G_SmithGGXCorrelated(float NoV, float NoL, float alpha) {
    // Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", G2 = 1 / (1 + Lambda(v) + Lambda(l)):
    //     G = 2 NoL NoV / (NoL sqrt(alpha^2 + (1 - alpha^2) NoV^2) + NoV sqrt(alpha^2 + (1 - alpha^2) NoL^2))
    // This is G, not Filament's V = G / (4 NoL NoV): the caller divides, as for every G.
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(a2 + (1.0 - a2) * NoV * NoV);
    float lambdaL = NoV * sqrt(a2 + (1.0 - a2) * NoL * NoL);
    return 2.0 * NoL * NoV / (lambdaV + lambdaL);
}

// ---- Fresnel F -------------------------------------------------------------------------

// Index of refraction n >= 1 with ((n - 1)/(n + 1))^2 = F0 (one channel):
//     n = (1 + sqrt F0) / (1 - sqrt F0),  written (1 + sqrt F0)^2 / (1 - F0)
// The second form is the same number without the cancellation of 1 - sqrt F0
// (1 - F0 is exact in float for F0 >= 0.5): at F0 = 0.999 the first loses 4 of
// float's 7 digits.
float iorFromF0(float F0) {
    float s = sqrt(clamp(F0, 0.0, 1.0));
    return (1.0 + s) * (1.0 + s) / max(1.0 - F0, MIN_ONE_MINUS_F0);
}

float fresnelDielectric(float F0, float c) {
    float n = iorFromF0(F0);
    if (n <= 1.0) return 0.0;  // F0 = 0: equal indices, no interface, nothing reflects
    float g = sqrt(n * n - 1.0 + c * c);  // > 0 since n > 1: no total internal reflection from outside
    float ratio = (g - c) / (g + c);
    float tail = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * ratio * ratio * (1.0 + tail * tail);
}

vec3 F_Dielectric(vec3 F0, float VoH) {
    // Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 22, unpolarised,
    // per channel with the index n that gives F0 at normal incidence:
    //     n = (1 + sqrt F0) / (1 - sqrt F0),  c = VoH,  g = sqrt(n^2 - 1 + c^2)
    //     F = 1/2 (g - c)^2 / (g + c)^2 (1 + ((c (g + c) - 1) / (c (g - c) + 1))^2)
    float c = clamp(VoH, 0.0, 1.0);
    return vec3(fresnelDielectric(F0.r, c), fresnelDielectric(F0.g, c), fresnelDielectric(F0.b, c));
}

float fresnelConductor(float F0, float edgeTint, float c) {
    float r = clamp(F0, 0.0, 1.0);
    float oneMinusR = max(1.0 - r, MIN_ONE_MINUS_F0);
    float g = clamp(edgeTint, 0.0, 1.0);  // Gulbrandsen's g is defined on [0, 1]
    float n = g * oneMinusR / (1.0 + r) + (1.0 - g) * iorFromF0(r);
    // r (n + 1)^2 - (n - 1)^2 rearranged to (r - 1)(n^2 + 1) + 2 n (r + 1), as
    // the CPU reference does; max(0, .): rounding must not make k imaginary.
    float k2 = max(0.0, (2.0 * n * (r + 1.0) - oneMinusR * (n * n + 1.0)) / oneMinusR);

    float cos2 = c * c;
    float sin2 = 1.0 - cos2;
    float t0 = n * n - k2 - sin2;
    float a2PlusB2 = sqrt(t0 * t0 + 4.0 * n * n * k2);
    float a = sqrt(max(0.0, 0.5 * (a2PlusB2 + t0)));  // max: a2PlusB2 >= |t0| up to rounding
    float t1 = a2PlusB2 + cos2;
    float t2 = 2.0 * c * a;
    float Rs = (t1 - t2) / (t1 + t2);
    float t3 = cos2 * a2PlusB2 + sin2 * sin2;
    float t4 = t2 * sin2;
    float Rp = Rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (Rs + Rp);
}

vec3 F_Conductor(vec3 F0, vec3 edgeTint, float VoH) {
    // Gulbrandsen 2014, "Artist Friendly Metallic Fresnel": (n, k) from reflectivity r = F0 and edge tint g,
    //     n = g (1 - r)/(1 + r) + (1 - g)(1 + sqrt r)/(1 - sqrt r),  k = sqrt((r (n + 1)^2 - (n - 1)^2) / (1 - r))
    // then the exact unpolarised conductor Fresnel (Pharr et al., PBR 3rd ed., sec. 8.2.1), s = sin, c = VoH:
    //     2 a^2 = sqrt((n^2 - k^2 - s^2)^2 + 4 n^2 k^2) + (n^2 - k^2 - s^2)
    //     Rs = (a^2 + b^2 - 2 a c + c^2) / (a^2 + b^2 + 2 a c + c^2)
    //     Rp = Rs (c^2 (a^2 + b^2) - 2 a c s^2 + s^4) / (c^2 (a^2 + b^2) + 2 a c s^2 + s^4),  F = (Rs + Rp) / 2
    float c = clamp(VoH, 0.0, 1.0);
    return vec3(fresnelConductor(F0.r, edgeTint.r, c), fresnelConductor(F0.g, edgeTint.g, c),
                fresnelConductor(F0.b, edgeTint.b, c));
}

// ---- diffuse ----------------------------------------------------------------------------

vec3 Fd_Burley(vec3 albedo, float NoV, float NoL, float LoH, float alpha) {
    // Burley 2012, "Physically-Based Shading at Disney":
    //     F90 = 0.5 + 2 alpha LoH^2
    //     f = albedo/pi (1 + (F90 - 1)(1 - NoL)^5) (1 + (F90 - 1)(1 - NoV)^5)
    // alpha = r^2 where Burley's notes put the perceptual r: as Filament's Fd_Burley and the CPU reference.
    float F90 = 0.5 + 2.0 * alpha * LoH * LoH;
    float lightScatter = 1.0 + (F90 - 1.0) * fifthPower(1.0 - NoL);
    float viewScatter = 1.0 + (F90 - 1.0) * fifthPower(1.0 - NoV);
    return Fd_Lambert(albedo) * (lightScatter * viewScatter);
}

// ---- Blinn-Phong (whole-model switch) ----------------------------------------------------

float shininessFromAlpha(float alpha) {
    // Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", the Phong lobe matched to GGX:
    //     s = 2 / alpha^2 - 2   (s = 0 at alpha = 1; 4.9e5 at the roughness clamp)
    return 2.0 / (alpha * alpha) - 2.0;
}

float Fr_BlinnPhong(vec3 n, vec3 h, float shininess) {
    // Blinn 1977, "Models of light reflection for computer synthesized pictures", with the exact energy
    // normalisation of the cosine-weighted lobe at normal incidence (Giesen 2009):
    //     f = (s + 2)(s + 4) / (8 pi (2^(-s/2) + s)) NoH^s,  0 for NoH <= 0
    // NoH^s as exp(s/2 ln NoH^2). Near the peak ln NoH^2 = ln(1 - |n x h|^2)
    // comes from |n x h|^2, which keeps its relative precision: NoH rounded to
    // float is off by up to 6e-8 there, which s = 4.9e5 (r = MIN_ROUGHNESS) would turn
    // into 3% (the cancellation D_GGX avoids). Away from the peak NoH itself is
    // the better-conditioned input (1 - |n x h|^2 would cancel instead).
    float s = shininess;
    float normalization = (s + 2.0) * (s + 4.0) / (8.0 * PI * (exp2(-0.5 * s) + s));
    float NoH = dot(n, h);
    if (NoH <= 0.0) return s == 0.0 ? normalization : 0.0;  // pow(0, s): 1 for s = 0
    vec3 NxH = cross(n, h);
    float x = dot(NxH, NxH);  // sin^2(theta_h) = 1 - NoH^2
    // ln(1 - x) by its Taylor series below x = 1e-2 (4 terms: truncation x^4/5 < 2e-9 relative).
    float lnNoH2 = x < 1e-2 ? -x * (1.0 + x * (0.5 + x * (1.0 / 3.0 + x * 0.25))) : 2.0 * log(NoH);
    return normalization * exp(0.5 * s * lnNoH2);
}

// ---- the BRDF of the scene's model -----------------------------------------------------------
// The counterparts of exercise 08's specularBRDF, diffuseBRDF and
// cookTorranceBRDF with the terms the defines select (Filament's
// distribution(), visibility(), fresnel() in brdf.fs do the same).

float modelD(vec3 n, vec3 h, float alpha) {
#ifdef RL_D_BECKMANN
    return D_Beckmann(n, h, alpha);
#else
    return D_GGX(n, h, alpha);
#endif
}

// Takes the perceptual roughness: the reference G_SchlickGGX remaps it itself.
float modelG(float NoV, float NoL, float roughness) {
#if defined(RL_G_SMITH_CORRELATED)
    return G_SmithGGXCorrelated(NoV, NoL, ggxAlpha(roughness));
#elif defined(RL_G_SMITH_SEPARABLE)
    return G_SmithGGXSeparable(NoV, NoL, ggxAlpha(roughness));
#else
    return G_SchlickGGX(NoV, NoL, roughness);
#endif
}

// Used by the specular lobe AND by the diffuse weight kd = (1 - F)(1 - metallic).
vec3 modelF(vec3 F0, vec3 edgeTint, float VoH) {
#if defined(RL_F_CONDUCTOR)
    return F_Conductor(F0, edgeTint, VoH);
#elif defined(RL_F_DIELECTRIC)
    return F_Dielectric(F0, VoH);
#else
    return F_Schlick(F0, VoH);
#endif
}

// Specular lobe, 0 when NoL = 0:
//     D G F / (4 NoL NoV),  NoV = clamp(n.v, 1e-4, 1)  (exercise 08's clamp and reason)
//     Blinn-Phong: F0 Fr_BlinnPhong(NoH, s)
vec3 modelSpecularBRDF(vec3 n, vec3 v, vec3 l, Material m, vec3 edgeTint) {
#ifndef RL_READY_cookTorranceBRDF  // the model's lobes come with 08 and the terms it builds on
    return vec3(0.0);
#endif
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    if (NoL == 0.0) return vec3(0.0);
    vec3 h = normalize(l + v);
#ifdef RL_BLINN_PHONG
    return baseReflectance(m) * Fr_BlinnPhong(n, h, shininessFromAlpha(ggxAlpha(m.roughness)));
#else
    float NoV = clamp(dot(n, v), 1e-4, 1.0);  // 1e-4: keeps 1/NoV finite at grazing view
    float D = modelD(n, h, ggxAlpha(m.roughness));
    float G = modelG(NoV, NoL, m.roughness);
    vec3 F = modelF(baseReflectance(m), edgeTint, dot(h, v));
    return D * G * F / (4.0 * NoL * NoV);
#endif
}

// Diffuse lobe kd Fd, kd = (1 - F)(1 - metallic), Fd = Fd_Lambert or Fd_Burley:
//     Blinn-Phong: (1 - F0)(1 - metallic) albedo/pi (no angle dependence)
// Like diffuseBRDF(), it does not look at NoL (modelBRDF does).
vec3 modelDiffuseBRDF(vec3 n, vec3 v, vec3 l, Material m, vec3 edgeTint) {
#ifndef RL_READY_cookTorranceBRDF
    return vec3(0.0);
#endif
#ifdef RL_BLINN_PHONG
    return (1.0 - baseReflectance(m)) * (1.0 - m.metallic) * Fd_Lambert(m.albedo);
#else
    vec3 h = normalize(l + v);
    float VoH = dot(v, h);
    vec3 kd = (1.0 - modelF(baseReflectance(m), edgeTint, VoH)) * (1.0 - m.metallic);
#ifdef RL_FD_BURLEY
    float NoV = clamp(dot(n, v), 1e-4, 1.0);  // the specular lobe's clamp, as the CPU reference
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    return kd * Fd_Burley(m.albedo, NoV, NoL, VoH, ggxAlpha(m.roughness));  // LoH = VoH
#else
    return kd * Fd_Lambert(m.albedo);
#endif
#endif
}

// The whole BRDF f(l, v) of the scene's model (linear, per steradian), 0 for
// a light at or below the horizon: what lighting.glsl's surfaceBRDF() uses
// in place of cookTorranceBRDF() when the scene has model variants; until
// 08 is ready, 08's neutral value like the reference model (Lambert alone).
vec3 modelBRDF(vec3 n, vec3 v, vec3 l, Material m, vec3 edgeTint) {
#ifndef RL_READY_cookTorranceBRDF
    return cookTorranceBRDF(n, v, l, m);
#endif
    if (dot(n, l) <= 0.0) return vec3(0.0);
    return modelDiffuseBRDF(n, v, l, m, edgeTint) + modelSpecularBRDF(n, v, l, m, edgeTint);
}
