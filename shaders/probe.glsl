// probe.glsl: evaluates ONE exercise function on a grid of inputs, for
// `raylab check` (probe.frag). The checker compiles it once per exercise with
// RL_PROBE_EXERCISE set, so only that exercise's functions are dispatched and
// the compiler drops the rest of the ray tracer (half the compile time).
// Case k is the pixel (k % width, k / width); its inputs are the six RGBA32F
// texels (6 (k % width) + i, k / width) of u_probeInputs, laid out as below;
// the result goes to the pixel's first output. The CPU side (each unit's
// probes.cpp, app/checks/probe_runner.cpp) writes the inputs and compares the results.

uniform sampler2D u_probeInputs;
uniform int u_probeFunction;  // a function's probe id (probeFunctionId, the units' functions in order), or PROBE_REINTERSECT

const int PROBE_REINTERSECT = -2;  // the re-intersection yardstick (tests/metamorphic/test_reintersect.cpp), not a check

const float PROBE_WRONG_ORIGIN = -2.0;  // traceRay: a bounce that does not start on the normal (course/09-reflections/probes.cpp)

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
    Hit hit = Hit(1.0, a.xyz, b.xyz, d.xyz, sphere, sphere >= 0 ? sphereGeometry(max(sphere, 0)) : vec4(0.0));
    vec4 r = vec4(0.0);
    int f = u_probeFunction;
    // The units' probe calls (course/*/unit.json, "probe"), written by the
    // host for the exercise RL_PROBE_EXERCISE (or every unit's).
#include "probe_dispatch.glsl"
#if !defined(RL_PROBE_EXERCISE) || RL_PROBE_EXERCISE == 4
    if (f == PROBE_REINTERSECT) r = reintersect(a.xyz, b.xyz, c.xyz, int(c.w));
#endif
    return r;
}
