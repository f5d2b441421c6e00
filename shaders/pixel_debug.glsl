// pixel_debug.glsl: the pixel debugger's recorder (pixel_debug.frag,
// app/render/pixel_debugger.h). The ray tracer of the implementation on
// screen traces ONE pixel's centre ray again in every fragment of a 1xN
// target; along the way each value of an exercise function is "recorded":
// the k-th value goes to the fragment of column k, as (value, key). Nothing
// but a draw and a float read-back: the same in WebGL2 (no SSBO, no atomics).
// Included by raytracer.glsl after lighting.glsl only with RL_PIXEL_DEBUG;
// trace.glsl's shadeHit() and backgroundRadiance(), the exercises' entries to
// the light, call debugShadeHit() and debugBackgroundRadiance() instead of
// lighting.glsl's hitRadiance() and missRadiance(), which these wrap.

// What a value is (the host's PixelValueKind, app/render/pixel_debugger.h).
const int DBG_SAMPLE_OFFSET = 1;   // 01 sampleOffset(0, n), n
const int DBG_CAMERA_RAY = 2;      // 01 cameraRayDirection at the pixel's centre
const int DBG_RAY = 10;            // the direction of the ray that made this hit (09 for a bounce)
const int DBG_HIT = 11;            // t, sphere (02 through closestHit)
const int DBG_POINT = 12;          // p (relative to the anchor, scene units)
const int DBG_NORMAL = 13;         // n
const int DBG_MISS = 14;           // the ray leaves the scene: the background
const int DBG_LIGHT_DIR = 18;      // l: the framework's inputs of 03-08 ...
const int DBG_HALF = 19;           // h
const int DBG_ANGLES = 20;         // n.l, n.v (both clamped as 08 clamps them), v.h
const int DBG_IRRADIANCE = 21;     // 03 pointLightIrradiance
const int DBG_LAMBERT = 22;        // 03 Fd_Lambert(albedo)
const int DBG_VISIBILITY = 23;     // 04 lightVisibility: 1 lit, 0 shadowed, -1 not asked (no light)
const int DBG_D = 24;              // 05 D_GGX(n, h, ggxAlpha(roughness))
const int DBG_G = 25;              // 06 G_SchlickGGX(NoV, NoL, roughness)
const int DBG_F = 26;              // 07 F_Schlick(baseReflectance, v.h)
const int DBG_ALPHA = 27;          // 08 ggxAlpha(roughness)
const int DBG_F0 = 28;             // 08 baseReflectance(m)
const int DBG_DIFFUSE = 29;        // 08 diffuseBRDF * E (0 in shadow)
const int DBG_SPECULAR = 30;       // 08 specularBRDF * E (0 in shadow)
const int DBG_BRDF = 31;           // 08 cookTorranceBRDF * E (0 in shadow): what the picture adds
const int DBG_SHADED = 32;         // shadeHit: every light + ambient (+ the environment's light)
// With an environment (RL_ENVIRONMENT), once per hit: exercise 11's functions
// on the inputs environmentHitLight() gives them (environment.glsl).
const int DBG_ENV_IRRADIANCE = 33;   // 11 shIrradiance(local n), times the intensity
const int DBG_ENV_LEVEL = 34;        // 11 prefilteredLevel(roughness, levels)
const int DBG_ENV_PREFILTERED = 35;  // the prefiltered chain at local reflect(-v, n), that level, times the intensity
const int DBG_ENV_SCALE_BIAS = 36;   // the split-sum table at (n.v, roughness): scale, bias
const int DBG_ENV_VISIBILITY = 37;   // 12 sphereFormFactor of the other spheres, summed
const int DBG_ENV_LIGHT = 38;        // 11 environmentShading(irradiance, prefiltered, scaleBias, m)
const int DBG_WEIGHT = 40;         // 09 traceRay's weight of bounce k (its throughput there)
const int DBG_RADIANCE = 41;       // 09 traceRay: the centre ray's radiance
const int DBG_DISPLAY = 50;        // 10 displayEncode, clamped: the display colour of that radiance

int g_debugSlot = -1;              // the value this fragment writes: its column
int g_debugCount = 0;              // values recorded so far
vec4 g_debugValue = vec4(0.0);     // key 0: past the last value
bool g_debugRecording = false;     // shadeHit() records its hit
bool g_debugUnitWeight = false;    // shadeHit() and backgroundRadiance() return 1 (at g_onlyBounce only)

// The key: kind + 100 * bounce + 10000 * (light + 1), exact in float32.
void debugRecord(int kind, int bounce, int light, vec3 value) {
    if (g_debugCount == g_debugSlot) g_debugValue = vec4(value, float(kind + 100 * bounce + 10000 * (light + 1)));
    ++g_debugCount;
}

// Everything the exercises compute at one hit, light by light, with the
// same inputs as the picture's shadeHit().
void debugRecordHit(Hit hit, vec3 v, Material m, int bounce) {
    debugRecord(DBG_RAY, bounce, -1, -v);
    debugRecord(DBG_HIT, bounce, -1, vec3(hit.t, float(hit.sphere), 0.0));
    debugRecord(DBG_POINT, bounce, -1, hit.p);
    debugRecord(DBG_NORMAL, bounce, -1, hit.n);
    for (int i = 0; i < lightCount(); ++i) {
        vec3 E = pointLightIrradiance(hit.p, hit.n, lightPosition(i), lightIntensity(i));
        vec3 l = normalize(lightPosition(i) - hit.p);
        vec3 h = normalize(l + v);
        float NoL = clamp(dot(hit.n, l), 0.0, 1.0);
        float NoV = clamp(dot(hit.n, v), 1e-4, 1.0);
        debugRecord(DBG_LIGHT_DIR, bounce, i, l);
        debugRecord(DBG_HALF, bounce, i, h);
        debugRecord(DBG_ANGLES, bounce, i, vec3(NoL, NoV, dot(v, h)));
        debugRecord(DBG_IRRADIANCE, bounce, i, E);
        debugRecord(DBG_LAMBERT, bounce, i, Fd_Lambert(m.albedo));
        float visibility = -1.0;
        if (E != vec3(0.0)) visibility = lightShadow(hit, i);  // as lightTerm(): no shadow ray where the light adds nothing
        debugRecord(DBG_VISIBILITY, bounce, i, vec3(visibility, 0.0, 0.0));
        // The material's inputs of D and F (08) before D, G, F themselves:
        // a wrong alpha is named as alpha, not as the D it feeds.
        debugRecord(DBG_ALPHA, bounce, i, vec3(ggxAlpha(m.roughness), 0.0, 0.0));
        debugRecord(DBG_F0, bounce, i, baseReflectance(m));
        debugRecord(DBG_D, bounce, i, vec3(D_GGX(hit.n, h, ggxAlpha(m.roughness)), 0.0, 0.0));
        debugRecord(DBG_G, bounce, i, vec3(G_SchlickGGX(NoV, NoL, m.roughness), 0.0, 0.0));
        debugRecord(DBG_F, bounce, i, F_Schlick(baseReflectance(m), dot(h, v)));
        vec3 lit = visibility > 0.0 ? E : vec3(0.0);
        debugRecord(DBG_DIFFUSE, bounce, i, diffuseBRDF(hit.n, v, l, m) * lit);
        debugRecord(DBG_SPECULAR, bounce, i, specularBRDF(hit.n, v, l, m) * lit);
        debugRecord(DBG_BRDF, bounce, i, cookTorranceBRDF(hit.n, v, l, m) * lit);
    }
#ifdef RL_ENVIRONMENT
    // The environment's terms, step by step as environmentHitLight() takes
    // them (read only: that function stays the picture's), before the
    // spheres' occlusion, which the debugger's program leaves out
    // (render/pixel_debugger.cpp); exercise 12's form factors of the other
    // spheres, summed, on a row of their own.
    float envNoV = clamp(dot(hit.n, v), 1e-4, 1.0);
    vec3 envE = u_envIntensity * shIrradiance(environmentLocal(hit.n));
    float envLevel = prefilteredLevel(m.roughness, u_envLevels);
    vec3 envPrefiltered = u_envIntensity * prefilteredRadiance(environmentLocal(reflect(-v, hit.n)), envLevel);
    vec2 envScaleBias = splitSumLookup(envNoV, m.roughness);
    float formFactors = 0.0;
    for (int k = 0; k < sphereCount(); ++k) {
        vec4 s = sphereGeometry(k);
        if (k == hit.sphere) continue;
        formFactors += length(s.xyz - hit.p) <= s.w ? 1.0 : sphereFormFactor(hit.p, hit.n, s.xyz, s.w);
    }
    debugRecord(DBG_ENV_IRRADIANCE, bounce, -1, envE);
    debugRecord(DBG_ENV_LEVEL, bounce, -1, vec3(envLevel, 0.0, 0.0));
    debugRecord(DBG_ENV_PREFILTERED, bounce, -1, envPrefiltered);
    debugRecord(DBG_ENV_SCALE_BIAS, bounce, -1, vec3(envScaleBias, 0.0));
    debugRecord(DBG_ENV_VISIBILITY, bounce, -1, vec3(formFactors, 0.0, 0.0));
    vec3 envLitE = envE;  // as environmentHitLight() takes it: the sun's correction, clamped at 0
#ifndef RL_ENV_IRRADIANCE_MAP
    envLitE += sunIrradianceCorrection(hit.n);
#endif
    debugRecord(DBG_ENV_LIGHT, bounce, -1, environmentShading(max(envLitE, vec3(0.0)), envPrefiltered, envScaleBias, m));
#endif
}

// shadeHit() of the debugger's program: this bounce's weight (1), or its
// values recorded on the way to the hit's radiance.
vec3 debugShadeHit(Hit hit, vec3 v, int bounce) {
    if (g_debugUnitWeight) return vec3(1.0);
    if (!g_debugRecording) return hitRadiance(hit, v);
    debugRecordHit(hit, v, sphereMaterial(hit.sphere), bounce);
    vec3 radiance = hitRadiance(hit, v);
    debugRecord(DBG_SHADED, bounce, -1, radiance);
    return radiance;
}

// backgroundRadiance() of the debugger's program; `kept`: the bounce view
// keeps this ray's light, `bounce`: the ray's place on the path (0: the camera's).
vec3 debugBackgroundRadiance(bool cameraRay, bool kept, int bounce) {
    if (g_debugRecording) debugRecord(DBG_MISS, bounce, -1, backgroundColour());
    if (g_debugUnitWeight) return kept ? vec3(1.0) : vec3(0.0);
    return kept ? missRadiance(cameraRay) : vec3(0.0);
}
