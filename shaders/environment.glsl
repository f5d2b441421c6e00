// environment.glsl: light from all around (issue 24, docs/model.md
// "Environment light"), compiled in only for a scene with an "environment"
// (RL_ENVIRONMENT, app/render/define_table.cpp); without one this file adds
// nothing but the checker's coefficients below, and a picture is what it was.
//
// THE SHADER API (docs/decisions.md, "Environment light in the GL picture";
// the host side is app/render/environment_resources.h):
//   uniform sampler2D u_envMap          the radiance map as read (RGB32F, W x H, row 0 the top), texture unit 1
//   uniform sampler2D u_envPrefiltered  the prefiltered levels in one RGB32F atlas, texture unit 2
//   uniform sampler2D u_envSplitSum     the split-sum table (RG32F, n.v along x, roughness along y), unit 3
//   uniform vec4  u_envLevelRect[8]     each level's texel rectangle in the atlas: x, y, width, height
//   uniform int   u_envLevels           levels in the atlas (level k: roughness k / (levels - 1))
//   uniform vec3  u_envSh[9]            the map's nine SH coefficients (image frame, no intensity)
//   uniform float u_envIntensity        the scene's intensity (a value: no recompile)
//   uniform vec2  u_envRotation         cos, sin of the scene's rotation about +y (a value: no recompile)
//   uniform sampler2D u_envIrradiance   only with RL_ENV_IRRADIANCE_MAP: the N x N/2 irradiance map
//                                       (RGBA32F, image frame, no intensity; environmentIrradianceMap()), unit 4
// DIFFUSE IRRADIANCE: the course's default, and what every picture of
// `raylab render`, the live view and the checker draw, stays exercise 11's
// shIrradiance() on the nine SH coefficients (SH9). Only a program compiled
// with RL_ENV_IRRADIANCE_MAP (the bench's env:irradiance-map=N rows,
// app/bench/environment_sweep.h) reads E(n) from the host's irradiance map
// instead, bilinear like the other textures: the comparison that says what
// SH9's band limit costs against a map's resolution.
// Every texture is read by texelFetch() and filtered here (bilinear as the
// reference's bilinearRadiance()), so 32-bit float textures serve in WebGL2
// too, where they cannot be filtered by the sampler.
// Functions: environmentRadiance(d) (what a ray sees), environmentHitLight()
// (what a hit adds: exercise 11's functions on the host's tables), and the
// lookups environmentLocal(), equirectUv(), prefilteredRadiance(), splitSumLookup().

const int ENV_MAX_LEVELS = 16;

#ifdef RL_ENVIRONMENT
uniform sampler2D u_envMap;
uniform sampler2D u_envPrefiltered;
uniform sampler2D u_envSplitSum;
uniform vec4 u_envLevelRect[ENV_MAX_LEVELS];
uniform int u_envLevels;
uniform vec3 u_envSh[9];
uniform float u_envIntensity;
uniform vec2 u_envRotation;
#ifdef RL_ENV_IRRADIANCE_MAP
uniform sampler2D u_envIrradiance;
#endif

// The k-th coefficient, for exercise 11's shIrradiance().
vec3 shCoefficient(int k) { return u_envSh[k]; }
#else
// The checker's probe program sets the coefficients of each case here
// (course/11-environment/unit.json, "probe").
vec3 g_probeSh[9];
vec3 shCoefficient(int k) { return g_probeSh[k]; }
#endif

#ifdef RL_ENVIRONMENT
// The direction of the last ray closestHit() followed (intersect_scene.glsl):
// what backgroundRadiance() looks up when that ray hits nothing.
vec3 g_rayDirection = vec3(0.0, 0.0, -1.0);

// A world direction in the image's own frame: turned by -rotation about +y.
vec3 environmentLocal(vec3 d) {
    float c = u_envRotation.x, s = u_envRotation.y;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// u = 1/2 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi (0 straight up).
vec2 equirectUv(vec3 d) {
    float u = d.x == 0.0 && d.z == 0.0 ? 0.5 : 0.5 + atan(d.x, -d.z) / (2.0 * PI);
    return vec2(u, acos(clamp(d.y, -1.0, 1.0)) / PI);
}

// Bilinear between texel centres of the rectangle `rect` of `t`, wrapping in
// u and clamped in v (app/core/environment_image.cpp, bilinearRadiance).
vec3 environmentBilinear(sampler2D t, vec4 rect, vec2 uv) {
    ivec2 origin = ivec2(rect.xy);
    int W = int(rect.z), H = int(rect.w);
    float x = uv.x * rect.z - 0.5;
    float y = clamp(uv.y * rect.w - 0.5, 0.0, rect.w - 1.0);
    float fx = floor(x), fy = floor(y);
    int x0 = int(fx);
    x0 = x0 < 0 ? x0 + W : (x0 >= W ? x0 - W : x0);
    int x1 = x0 + 1 >= W ? 0 : x0 + 1;
    int y0 = int(fy);
    int y1 = min(y0 + 1, H - 1);
    vec3 c00 = texelFetch(t, origin + ivec2(x0, y0), 0).rgb;
    vec3 c10 = texelFetch(t, origin + ivec2(x1, y0), 0).rgb;
    vec3 c01 = texelFetch(t, origin + ivec2(x0, y1), 0).rgb;
    vec3 c11 = texelFetch(t, origin + ivec2(x1, y1), 0).rgb;
    float ax = x - fx, ay = y - fy;
    return mix(mix(c00, c10, ax), mix(c01, c11, ax), ay);
}

// Radiance arriving from the world direction d (unit): L(d).
vec3 environmentRadiance(vec3 d) {
    vec2 size = vec2(textureSize(u_envMap, 0));
    return u_envIntensity * environmentBilinear(u_envMap, vec4(0.0, 0.0, size), equirectUv(environmentLocal(d)));
}

// The prefiltered environment (no intensity) towards the image-frame
// direction r at a fractional level: linear between the two levels around it.
vec3 prefilteredRadiance(vec3 r, float level) {
    float l = clamp(level, 0.0, float(u_envLevels - 1));
    int k0 = int(floor(l));
    int k1 = min(k0 + 1, u_envLevels - 1);
    vec2 uv = equirectUv(r);
    vec3 a = environmentBilinear(u_envPrefiltered, u_envLevelRect[k0], uv);
    vec3 b = environmentBilinear(u_envPrefiltered, u_envLevelRect[k1], uv);
    return mix(a, b, l - float(k0));
}

// The split-sum table's (scale, bias) at n.v and perceptual roughness
// (clamped to [MIN_ROUGHNESS, 1], as the table), bilinear between texel centres,
// clamped at the edges.
vec2 splitSumLookup(float NoV, float roughness) {
    ivec2 size = textureSize(u_envSplitSum, 0);
    vec2 p = clamp(vec2(NoV, clamp(roughness, MIN_ROUGHNESS, 1.0)) * vec2(size) - 0.5, vec2(0.0), vec2(size - 1));
    vec2 f = floor(p);
    ivec2 i0 = ivec2(f);
    ivec2 i1 = min(i0 + 1, size - 1);
    vec2 a = p - f;
    vec2 s00 = texelFetch(u_envSplitSum, ivec2(i0.x, i0.y), 0).rg;
    vec2 s10 = texelFetch(u_envSplitSum, ivec2(i1.x, i0.y), 0).rg;
    vec2 s01 = texelFetch(u_envSplitSum, ivec2(i0.x, i1.y), 0).rg;
    vec2 s11 = texelFetch(u_envSplitSum, ivec2(i1.x, i1.y), 0).rg;
    return mix(mix(s00, s10, a.x), mix(s01, s11, a.x), a.y);
}

// The map's sun (app/render/environment_caps.h, findSun): its world direction
// (xyz) and the angular radius of a disc of its solid angle (w; 0: the map
// has none), and its power (the sum of L dOmega over its pixels, no
// intensity).
uniform vec4 u_envSun;
uniform vec3 u_envSunPower;

// What SH9 makes of the sun (its power above the sky around it, Phi, at s):
// nine coefficients of a small source give it the irradiance
// Phi (1/4 + x/2 + 5/16 (3x^2 - 1)/2), x = n.s (the clamped cosine's first
// three bands, docs/model.md), 7% short of Phi max(x, 0) at 55 degrees and
// below zero opposite the sun (world n, with intensity).
vec3 sunShIrradiance(vec3 n) {
    if (u_envSun.w <= 0.0) return vec3(0.0);
    float x = dot(n, u_envSun.xyz);
    return u_envIntensity * u_envSunPower * (0.25 + 0.5 * x + 0.3125 * (1.5 * x * x - 0.5));
}

// The sun as a point source: Phi max(n.s, 0) in place of its three bands
// (the pixel debugger's irradiance, pixel_debug.glsl).
vec3 sunIrradianceCorrection(vec3 n) {
    if (u_envSun.w <= 0.0) return vec3(0.0);
    return u_envIntensity * u_envSunPower * max(dot(n, u_envSun.xyz), 0.0) - sunShIrradiance(n);
}

// The light the sun sends towards v, a directional light of irradiance Phi
// (times its visible share) through the scene's BRDF (exercise 08): the
// BRDF's mean over the disc (radius theta_s = u_envSun.w), by the lobe's
// width alpha against the disc's:
//  * alpha >= theta_s: the BRDF at the disc's centre s with alpha widened to
//    sqrt(alpha^2 + (theta_s / 2)^2) (the disc's half-vector spread added:
//    the lobe convolved with the disc), exact for a lobe much wider than it;
//  * alpha <= theta_s / 2: read towards the disc's point nearest the mirror
//    direction (Karis 2013, "Real shading in Unreal Engine 4", sphere
//    lights: the "representative point"), so a mirror shows the disc, not a
//    point; the smaller of that BRDF at alpha and at the widened alpha, so
//    that a lobe as wide as the disc keeps its energy instead of the point's
//    peak times the disc's area;
//  * between, the two mixed by a smoothstep in alpha / theta_s.
// The representative point read for every lobe overstated a rough
// surface's sun glare (the BRDF at the disc's point nearest r is the
// disc's largest, not its mean): on a ground of roughness 0.6 under the sky
// by up to 2.5 LSB (docs/decisions.md, "The sun's glare on rough surfaces").
// app/reference/pixel_breakdown.cpp (the pixel debugger's double side)
// computes the same, with the same two bounds.
const float SUN_DISC_POINT_BELOW = 0.5;  // alpha / theta_s: the representative point below
const float SUN_DISC_CENTRE_FROM = 1.0;  // alpha / theta_s: the disc's centre from
vec3 hitBRDF(Hit hit, vec3 v, vec3 l, Material m);  // lighting.glsl
vec3 sunLight(Hit hit, vec3 v, Material m, vec3 reflected, float visible) {
    if (u_envSun.w <= 0.0 || visible <= 0.0) return vec3(0.0);
    vec3 s = u_envSun.xyz;
    float NoS = dot(hit.n, s);
    if (NoS <= 0.0) return vec3(0.0);
    float r = clamp(m.roughness, MIN_ROUGHNESS, 1.0);
    Material wide = m;
    wide.roughness = sqrt(min(length(vec2(r * r, 0.5 * u_envSun.w)), 1.0));
    float centre = smoothstep(SUN_DISC_POINT_BELOW, SUN_DISC_CENTRE_FROM, r * r / u_envSun.w);
    vec3 f = centre > 0.0 ? hitBRDF(hit, v, s, wide) : vec3(0.0);
    if (centre < 1.0) {
        float apart = acos(clamp(dot(reflected, s), -1.0, 1.0));
        vec3 l = s;
        if (apart > 1e-6) {
            vec3 towards = normalize(reflected - dot(reflected, s) * s);
            float a = min(apart, u_envSun.w);
            l = cos(a) * s + sin(a) * towards;
        }
        f = mix(min(hitBRDF(hit, v, l, m), hitBRDF(hit, v, l, wide)), f, centre);
    }
    return visible * f * u_envIntensity * u_envSunPower * NoS;
}

#if defined(RL_ENV_OCCLUSION) && RL_ENV_OCCLUSION != 0
#include "environment_occlusion.glsl"  // the spheres' caps taken out of both parts
#endif

// The environment light a hit sends towards v: exercise 11's diffuse and
// specular parts on the host's tables, with RL_ENV_OCCLUSION shadowed by the
// other spheres (environment_occlusion.glsl); without it the integral with
// V = 1 (docs/model.md, "Environment light"). SH9 irradiance rings below
// zero opposite a small bright source: it is clamped at 0, as the light it
// stands for.
vec3 environmentHitLight(Hit hit, vec3 v, Material m) {
    float NoV = clamp(dot(hit.n, v), 1e-4, 1.0);
#ifdef RL_ENV_IRRADIANCE_MAP
    vec2 irradianceSize = vec2(textureSize(u_envIrradiance, 0));
    vec3 E = u_envIntensity *
             environmentBilinear(u_envIrradiance, vec4(0.0, 0.0, irradianceSize), equirectUv(environmentLocal(hit.n)));
#else
    vec3 E = u_envIntensity * shIrradiance(environmentLocal(hit.n));
#endif
#ifndef RL_ENV_IRRADIANCE_MAP
    E -= sunShIrradiance(hit.n);  // the sun is added below as a light of its own
#endif
    E = max(E, vec3(0.0));
    vec3 reflected = reflect(-v, hit.n);
    vec3 prefiltered =
        u_envIntensity * prefilteredRadiance(environmentLocal(reflected), prefilteredLevel(m.roughness, u_envLevels));
#if defined(RL_ENV_OCCLUSION) && RL_ENV_OCCLUSION != 0
    OccludedLight kept = occludeEnvironment(hit, reflected, m.roughness, E, prefiltered);
    E = kept.irradiance;
    prefiltered = kept.prefiltered;
    float sunVisible = kept.sun;
#else
    float sunVisible = 1.0;
#endif
    return environmentShading(E, prefiltered, splitSumLookup(NoV, m.roughness), m) +
           sunLight(hit, v, m, reflected, sunVisible);
}
#endif
