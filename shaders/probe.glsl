// probe.glsl: evaluates ONE exercise function on a grid of inputs, for
// `raylab check` (probe.frag). The checker compiles it once per exercise with
// RL_PROBE_EXERCISE set, so only that exercise's functions are dispatched and
// the compiler drops the rest of the ray tracer (half the compile time).
// Case k is the pixel (k % width, k / width); its inputs are the six RGBA32F
// texels (6 (k % width) + i, k / width) of u_probeInputs, laid out as below;
// the result goes to the pixel's first output. The CPU side
// (app/checks/probe_cases.cpp) writes the inputs and compares the results.

uniform sampler2D u_probeInputs;
uniform int u_probeFunction;  // one of the PROBE_ constants (probe_cases.h has the same list)

const int PROBE_SAMPLE_OFFSET = 0;
const int PROBE_CAMERA_RAY = 1;
const int PROBE_INTERSECT = 2;
const int PROBE_LAMBERT = 3;
const int PROBE_IRRADIANCE = 4;
const int PROBE_OFFSET_ORIGIN = 5;
const int PROBE_VISIBILITY = 6;
const int PROBE_D_GGX = 7;
const int PROBE_G1 = 8;
const int PROBE_G = 9;
const int PROBE_F_SCHLICK = 10;
const int PROBE_ALPHA = 11;
const int PROBE_F0 = 12;
const int PROBE_SPECULAR = 13;
const int PROBE_DIFFUSE = 14;
const int PROBE_BRDF = 15;
const int PROBE_F_ROUGHNESS = 16;
const int PROBE_TRACE = 17;
const int PROBE_TONEMAP = 18;
const int PROBE_GAMMA = 19;
const int PROBE_DISPLAY = 20;
const int PROBE_REINTERSECT = 21;  // the re-intersection yardstick (tests/metamorphic/test_reintersect.cpp), not a check

const float PROBE_WRONG_ORIGIN = -2.0;  // traceRay: a bounce that does not start on the normal (probe_cases.cpp)

// pbrt-v4's re-intersection test (shapes_test.cpp, FullSphere.Reintersect)
// on the framework's hits: a ray from o along d meets the scene's sphere
// 0; from that hit a ray leaves along w, and must not meet the same surface
// again. `mode`: 0 the offset alone (offsetRayOrigin, exercise 04; the ray
// asks every sphere, its own included), 1 the offset and the framework's
// handling of the sphere a ray leaves (closestHit's `leaving`), 2 the bounce
// of 09: the same along reflect(d, n). Returns x 1 when the first ray hit,
// y the sphere the second ray meets (-1: none), z its t, w dot(w, n).
vec4 reintersect(vec3 o, vec3 d, vec3 w, int mode) {
    Hit first = closestHit(o, d, NO_SPHERE);
    if (first.t == NO_HIT) return vec4(0.0, -1.0, 0.0, 0.0);
    if (mode == 2) w = normalize(reflect(d, first.n));
    vec3 origin = offsetRayOrigin(first.p, first.n, first.error);
    Hit second = closestHit(origin, w, mode == 0 ? NO_SPHERE : first.sphere);
    return vec4(1.0, float(second.sphere), second.t, dot(w, first.n));
}

vec4 evaluateProbe() {
    ivec2 cell = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(u_probeInputs, ivec2(6 * cell.x + 0, cell.y), 0);
    vec4 b = texelFetch(u_probeInputs, ivec2(6 * cell.x + 1, cell.y), 0);
    vec4 c = texelFetch(u_probeInputs, ivec2(6 * cell.x + 2, cell.y), 0);
    vec4 d = texelFetch(u_probeInputs, ivec2(6 * cell.x + 3, cell.y), 0);
    vec4 e = texelFetch(u_probeInputs, ivec2(6 * cell.x + 4, cell.y), 0);
    Material m = Material(a.xyz, a.w, b.x, b.y);
    // visibility: p, n, light (c), error, sphere (NO_SPHERE: only the offset keeps the ray off the surface)
    int sphere = int(d.w);
    Hit hit = Hit(1.0, a.xyz, b.xyz, d.xyz, sphere, sphere >= 0 ? u_sphereGeometry[max(sphere, 0)] : vec4(0.0));
    vec4 r = vec4(0.0);
    int f = u_probeFunction;
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 1
    if (f == PROBE_SAMPLE_OFFSET) r.xy = sampleOffset(int(a.x), int(a.y));
    if (f == PROBE_CAMERA_RAY) r.xyz = cameraRayDirection(a.xy, a.zw, b.x, c.xyz, d.xyz, e.xyz);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 2
    if (f == PROBE_INTERSECT) r.x = intersectSphere(a.xyz, b.xyz, c.xyz, c.w);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 3
    if (f == PROBE_LAMBERT) r.xyz = Fd_Lambert(a.xyz);
    if (f == PROBE_IRRADIANCE) r.xyz = pointLightIrradiance(a.xyz, b.xyz, c.xyz, d.xyz);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 4
    if (f == PROBE_OFFSET_ORIGIN) r.xyz = offsetRayOrigin(a.xyz, b.xyz, c.xyz);
    if (f == PROBE_VISIBILITY) r.x = lightVisibility(hit, c.xyz);
    if (f == PROBE_REINTERSECT) r = reintersect(a.xyz, b.xyz, c.xyz, int(c.w));
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 5
    if (f == PROBE_D_GGX) r.x = D_GGX(a.xyz, b.xyz, c.x);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 6
    if (f == PROBE_G1) r.x = G1_SchlickGGX(a.x, a.y);
    if (f == PROBE_G) r.x = G_SchlickGGX(a.x, a.y, a.z);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 7
    if (f == PROBE_F_SCHLICK) r.xyz = F_Schlick(a.xyz, a.w);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 8
    if (f == PROBE_ALPHA) r.x = ggxAlpha(a.x);
    if (f == PROBE_F0) r.xyz = baseReflectance(m);
    if (f == PROBE_SPECULAR) r.xyz = specularBRDF(c.xyz, d.xyz, e.xyz, m);
    if (f == PROBE_DIFFUSE) r.xyz = diffuseBRDF(c.xyz, d.xyz, e.xyz, m);
    if (f == PROBE_BRDF) r.xyz = cookTorranceBRDF(c.xyz, d.xyz, e.xyz, m);
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 9
    if (f == PROBE_F_ROUGHNESS) r.xyz = F_SchlickRoughness(a.xyz, a.w, b.x);
    if (f == PROBE_TRACE) {
        r.xyz = traceRay(a.xyz, b.xyz);
        // The bounce must start at offsetRayOrigin(hit.p, hit.n, hit.error):
        // pushed along the normal, not along the reflected ray. Further than a
        // quarter of the offset from it (rounding is ~1/12 of it), the case
        // reads PROBE_WRONG_ORIGIN, which the checker names.
        Hit h = g_probeFirstHit;
        if (r.x != NOT_STARTED && g_probeCalls > 1 && h.t != NO_HIT) {
            float offset = dot(abs(h.n), h.error);
            if (length(g_probeSecondOrigin - (h.p + offset * h.n)) > 0.25 * offset) r.xyz = vec3(PROBE_WRONG_ORIGIN);
        }
    }
#endif
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 10
    if (f == PROBE_TONEMAP) r.xyz = toneMap(a.xyz, int(a.w));
    if (f == PROBE_GAMMA) r.xyz = encodeGamma(a.xyz, a.w);
    if (f == PROBE_DISPLAY) r.xyz = displayEncode(a.xyz, a.w, int(b.x), b.y);
#endif
    return r;
}
