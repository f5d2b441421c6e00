// intersect_scene.glsl: rays against every sphere of the scene, built on the
// exercise's intersectSphere() (02-intersect) and on error_bounds.glsl.
//
// `leaving` is the sphere the ray's origin lies on (Hit.sphere of the hit it
// starts from), or NO_SPHERE for a camera ray. That sphere is never asked
// again: it is handled exactly, once per ray (leavingSphereHit: skipped when
// the ray leaves its outside, its far root when the ray crosses its inside).

#if defined(RL_PROBE_EXERCISE) && RL_PROBE_EXERCISE == 9
// `raylab check` of exercise 09 (probe.glsl): the first hit of traceRay() and
// the origin of the ray after it, to see that the bounce starts on the normal.
int g_probeCalls = 0;
Hit g_probeFirstHit;
vec3 g_probeSecondOrigin;
#endif

// Nearest hit along `dir`; hit.t = NO_HIT when nothing is hit. `dir` is
// renormalised first: a reflected direction is unit length only to ~1e-7,
// and intersectSphere() assumes |dir| = 1 (over a chord of 8 that is 8e-6).
// Every other sphere's root comes from the exercise and is refined
// (refineRoot), so that the nearest is found among exact-as-float32 roots.
Hit closestHit(vec3 origin, vec3 dir, int leaving) {
    dir = normalize(dir);
    Hit hit;
    hit.t = NO_HIT;
    hit.sphere = NO_SPHERE;
    float nearest = 3.4e38;  // FLT_MAX: any real hit is nearer
    int sphere = NO_SPHERE;
    vec4 geometry = vec4(0.0), leavingGeometry = vec4(0.0);  // centre and radius of the nearest, of `leaving`
    float cameraC = 0.0, leavingC = 0.0;  // sphereCameraC() of the nearest, of `leaving`
    bool residual = true, leavingResidual = true;  // residualFormCandidate() of the nearest, of `leaving`
    for (int i = 0; i < sphereCount(); ++i) {
        vec4 sphereI = u_sphereGeometry[i];
        float t = intersectSphere(origin, dir, sphereI.xyz, sphereI.w);
        if (isGeometryStub(t)) return hit;  // 02 not started: nothing is hit
        if (i == leaving) {
            leavingGeometry = sphereI;
#ifdef RL_SPHERE_COUNT
            leavingC = sphereCameraC(i);
            leavingResidual = residualFormCandidate(i);
#endif
        }
        if (t > 0.0 && i != leaving) {
            if (refinesRoot(i)) t = refineRoot(origin, dir, i, t);
            if (t > 0.0 && t < nearest) {
                nearest = t;
                sphere = i;
                geometry = sphereI;
#ifdef RL_SPHERE_COUNT  // unrolled: a direct load; a loop would gather it for every sphere
                cameraC = sphereCameraC(i);
                residual = residualFormCandidate(i);  // a constant: the residual form folds away where no sphere needs it
#endif
            }
        }
    }
    if (leaving != NO_SPHERE) {
        float t = leavingSphereHit(origin, dir, leavingGeometry);
        if (t > 0.0 && t < nearest) {
            nearest = t;
            sphere = leaving;
            geometry = leavingGeometry;
            cameraC = leavingC;
            residual = leavingResidual;
        }
    }
#ifndef RL_SPHERE_COUNT
    if (sphere != NO_SPHERE) cameraC = sphereCameraC(sphere);
#endif
    if (sphere != NO_SPHERE) hit = makeHit(origin, dir, nearest, sphere, geometry, cameraC, residual);
#if defined(RL_PROBE_EXERCISE) && RL_PROBE_EXERCISE == 9
    if (g_probeCalls == 0) g_probeFirstHit = hit;
    if (g_probeCalls == 1) g_probeSecondOrigin = origin;
    ++g_probeCalls;
#endif
    return hit;
}

// True when some sphere other than `leaving` is hit at 0 < t < tMax. Stops
// at the first occluder: a shadow ray needs to know only whether, not where
// (the exercise's root is not refined: it decides only against tMax). The
// sphere a shadow ray leaves is decided before, exactly (lighting.glsl,
// shadowVisibility): from outside it hides nothing the ray goes to, from
// inside it hides every light outside it.
//
// A program for one picture knows where everything is: RL_OCCLUDERS lists,
// per light, the spheres that can lie between that light and some point of
// another sphere (a bit mask per light, computed in double by
// occluderDefines(), app/render/specialisation.cpp); the others are left out
// of that light's shadow rays. g_shadowLight is the light directLight() asks
// about (lighting.glsl); -1 (views, probes): every sphere may occlude.
int g_shadowLight = -1;

bool mayOcclude(int light, int i) {
#ifdef RL_OCCLUDERS
    const int occluders[RL_LIGHT_COUNT] = int[RL_LIGHT_COUNT](RL_OCCLUDERS);
    return light < 0 || ((occluders[light] >> i) & 1) != 0;
#else
    return true;
#endif
}

bool anyHitBefore(vec3 origin, vec3 dir, float tMax, int leaving) {
    for (int i = 0; i < sphereCount(); ++i) {
        if (!mayOcclude(g_shadowLight, i)) continue;
        float t = intersectSphere(origin, dir, sphereCenter(i), sphereRadius(i));
        if (t > 0.0 && t < tMax && i != leaving) return true;
    }
    return false;
}
