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

int g_shadowLight = -1;  // the light of the shadow ray in flight (lightShadow(), lighting.glsl; -1: none known)

// The exercise's root t on sphere i, or where its float32 cannot tell which
// side of the sphere the ray starts on (a camera or a point a float32 step
// above a huge sphere, issue #23), the root from a better C: the host's for a
// camera ray, the anchor form's for a secondary ray near a huge sphere. Only
// there does the framework overrule the exercise; elsewhere a huge sphere's
// root is refined (refineRoot) and a student's mistakes show as they are.
float sideCheckedRoot(vec3 origin, vec3 dir, vec4 sphere, int i, float t, bool fromCamera) {
    if (fromCamera && cameraSideFromHost(i)) return rootFromC(origin, dir, sphere.xyz, cameraC(i));
    if (!refinesRoot(i)) return t;
    bool decided;
    float better = anchorSideRoot(origin, dir, sphere, sphereAnchorC(i), decided);
    if (decided) return better;
    return t > 0.0 ? refineRoot(origin, dir, sphere, sphereAnchorC(i), t) : t;
}

// The nearest hit so far of closestHit(), and what it needs of two spheres:
// the nearest's and the one the ray leaves (their geometry, sphereAnchorC()
// and residualFormCandidate()), picked up by selects as the spheres go by: a
// sphere's numbers are then constants in a specialised program, where
// indexing them by a pixel's sphere would cost a chain of selects per use.
struct Nearest {
    float t;
    int sphere;
    vec4 geometry;
    float anchorC;
    bool residual;
    vec4 leavingGeometry;
    float leavingC;
    bool leavingResidual;
};

// Sphere i's root by the exercise (side-checked), kept if nearer. Selects,
// not an `if`: llvmpipe runs the body of an if for every pixel anyway, and
// the selects measured 2% to 4% faster (docs/performance.md).
void nearestStep(int i, vec3 origin, vec3 dir, int leaving, bool fromCamera, inout Nearest n) {
    vec4 sphereI = sphereGeometry(i);
    float anchorCi = sphereAnchorC(i);
    bool residualI = residualFormCandidate(i);
    bool isLeaving = i == leaving;
    n.leavingGeometry = isLeaving ? sphereI : n.leavingGeometry;
    n.leavingC = isLeaving ? anchorCi : n.leavingC;
    n.leavingResidual = isLeaving ? residualI : n.leavingResidual;
    float t = intersectSphere(origin, dir, sphereI.xyz, sphereI.w);
    t = sideCheckedRoot(origin, dir, sphereI, i, t, fromCamera);  // unused for `leaving`
    bool nearer = t > 0.0 && t < n.t && !isLeaving;
    n.t = nearer ? t : n.t;
    n.sphere = nearer ? i : n.sphere;
    n.geometry = nearer ? sphereI : n.geometry;
    n.anchorC = nearer ? anchorCi : n.anchorC;
    n.residual = nearer ? residualI : n.residual;
}

// Nearest hit along `dir`; hit.t = NO_HIT when nothing is hit. `dir` is
// renormalised first: a reflected direction is unit length only to ~1e-7,
// and intersectSphere() assumes |dir| = 1 (over a chord of 8 that is 8e-6).
// Every other sphere's root comes from the exercise, side-checked and, on a
// huge sphere, refined (sideCheckedRoot), so that the nearest is found among
// exact-as-float32 roots. The sphere the ray leaves is never asked again: a
// ray leaving its outside cannot meet it (it is convex), one crossing its
// inside meets it at the far root (leavingSphereHit), whatever the offset.
//
// In the sky tiles' program (RL_SKY: the host found that no camera ray of
// the model through these pixels can reach a sphere, render/sky_tiles.h)
// every ray is still tested with the exercise's intersection, and the hit is
// not shaded but reported: the pixel is marked (g_assumptionBroken) and the
// picture program draws it again. A ray that misses, as every camera ray of
// a correct 01 and 02 does there, sees the background: the same pixel as
// the picture program's, without its shading code.
Hit closestHit(vec3 origin, vec3 dir, int leaving) {
    dir = normalize(dir);
#ifdef RL_ENVIRONMENT
    g_rayDirection = dir;  // what backgroundRadiance() sees if this ray hits nothing (environment.glsl)
#endif
    // A camera ray: the host knows the camera's side of every sphere (issue #23).
    bool fromCamera = leaving == NO_SPHERE && origin == cameraFromAnchor();
    Nearest n = Nearest(3.4e38, NO_SPHERE, vec4(0.0), 0.0, true, vec4(0.0), 0.0, true);  // FLT_MAX: any real hit is nearer
#ifdef RL_FOR_EACH_SPHERE  // every index a constant (define_table.cpp)
#define RL_NEAREST_STEP(i) nearestStep(i, origin, dir, leaving, fromCamera, n);
    RL_FOR_EACH_SPHERE(RL_NEAREST_STEP)
#else
    for (int i = 0; i < sphereCount(); ++i) nearestStep(i, origin, dir, leaving, fromCamera, n);
#endif
    Hit hit;
    hit.t = NO_HIT;
    hit.sphere = NO_SPHERE;
#ifdef RL_SKY
    if (n.sphere != NO_SPHERE || leaving != NO_SPHERE) g_assumptionBroken = true;
    return hit;
#endif
    if (leaving != NO_SPHERE) {
        float t = leavingSphereHit(origin, dir, n.leavingGeometry);
        bool nearer = t > 0.0 && t < n.t;
        n.t = nearer ? t : n.t;
        n.sphere = nearer ? leaving : n.sphere;
        n.geometry = nearer ? n.leavingGeometry : n.geometry;
        n.anchorC = nearer ? n.leavingC : n.anchorC;
        n.residual = nearer ? n.leavingResidual : n.residual;
    }
    if (n.sphere != NO_SPHERE) hit = makeHit(origin, dir, n.t, n.sphere, n.geometry, n.anchorC, n.residual);
#if defined(RL_PROBE_EXERCISE) && RL_PROBE_EXERCISE == 9
    if (g_probeCalls == 0) g_probeFirstHit = hit;
    if (g_probeCalls == 1) g_probeSecondOrigin = origin;
    ++g_probeCalls;
#endif
    return hit;
}

// True when some sphere other than `leaving` is hit at 0 < t < tMax. Stops
// at the first occluder: a shadow ray needs to know only whether, not where.
// The sphere a shadow ray leaves is decided before, exactly (lighting.glsl,
// shadowVisibility): from outside it hides nothing the ray goes to, from
// inside it hides every light outside it.
//
// In a program specialised to the scene, a shadow ray towards light k
// (g_shadowLight, a constant where lighting.glsl's light terms are written
// out one by one) takes each sphere's test from the light's side where the
// host found that form exact for every light (shadow_light_side.glsl), the
// segment test elsewhere: RL_SHADOW_STEPS(X, Y) writes the spheres out one
// by one, X or Y each, so that every index, and with it every sphere's
// numbers, is a constant, and no program holds both forms of one sphere.
bool anyHitBefore(vec3 origin, vec3 dir, float tMax, int leaving) {
#ifdef RL_SHADOW_STEPS
    int k = g_shadowLight;
    if (k >= 0) {
        vec3 u = lightPosition(k) - origin;
        float d2 = dot(u, u);
        if (!segmentEndsAtLight(origin, dir, tMax, lightPosition(k), d2)) g_assumptionBroken = true;
        bool blocked = false;
#define RL_LIGHT_SIDE_STEP(j) blocked = blocked || (j != leaving && lightSideBlocks(LIGHT_OCCLUDERS[k * RL_SPHERE_COUNT + j], u, d2));
#define RL_SEGMENT_STEP(j) blocked = blocked || (j != leaving && blocksSegment(origin, dir, tMax, j, k));
        RL_SHADOW_STEPS(RL_LIGHT_SIDE_STEP, RL_SEGMENT_STEP)
        return blocked;
    }
#endif
    for (int i = 0; i < sphereCount(); ++i)
        if (i != leaving && blocksSegment(origin, dir, tMax, i, g_shadowLight)) return true;
    return false;
}
