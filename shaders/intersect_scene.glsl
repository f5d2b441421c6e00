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

// ---- Candidates (RL_CANDIDATE_SHADOWS, a program for one picture) --------------------------
//
// llvmpipe runs every line of unrolled code for all 8 pixels it shades
// together, but a loop only as often as the pixel that needs it most. So a
// program for one picture first asks each sphere a cheap question, "can this
// ray come near it at all?" (mayHitSphere: a few dot products, no root, no
// division), collects the spheres that can in a bit mask, and runs the
// shadow test proper (blocksSegment) in a loop over those only. mayHitSphere()
// never says no to a sphere the test proper would find (its margins cover
// float32's rounding many times over), so the picture stays the same; a
// sphere it lets through in vain costs one turn of the loop.

// Whether o + t d, 0 < t < tMax (d unit), can meet the sphere (xyz centre,
// w radius). A hit needs the ray's closest approach b = (c - o).d within
// [-r, tMax + r] and its squared distance from the centre |c - o|^2 - b^2
// at most r^2. Both sides round by a few u of |c - o|^2 (b^2 cancels against
// |c - o|^2 for a far sphere near the ray): the margins, 1e-5 of the terms,
// are 40 times that.
bool mayHitSphere(vec3 o, vec3 d, float tMax, vec4 sphere) {
    vec3 f = sphere.xyz - o;
    float b = dot(f, d);
    float ff = dot(f, f);
    float rr = sphere.w * sphere.w;
    float margin = 1e-5 * (ff + rr);
    return ff - b * b <= rr + margin && b + sphere.w >= -1e-5 * (abs(b) + sphere.w) && b - sphere.w <= tMax + 1e-5 * abs(b);
}

#ifdef RL_SHADOW_CONES
// The same question from the light's side (RL_SHADOW_CONES: a program for one
// picture with the course's 02 and 04; app/render/shadow_cones.h). Seen from
// light k, sphere i covers a cone of directions around the axis from the
// light to its centre; a shadow ray towards the light can cross the sphere
// only if its reversed direction lies in that cone and the ray is longer
// than the light's distance to the sphere. The host computes both in double,
// widened far beyond float32's rounding, and compiles them in: one dot
// product against a constant, where mayHitSphere() takes three.
const vec4 SHADOW_CONE_AXIS[] = RL_SHADOW_CONE_AXIS;         // xyz: axis, w: the least cosine
const float SHADOW_CONE_NEAREST[] = RL_SHADOW_CONE_NEAREST;  // the least tMax
#endif
int g_shadowLight = -1;  // the light of the shadow ray in flight (directLight sets it; -1: a probe's own light)

bool mayShadow(vec3 origin, vec3 dir, float tMax, int i) {
#ifdef RL_SHADOW_CONES
    int cone = g_shadowLight * RL_SPHERE_COUNT + i;  // a constant: lights and spheres are unrolled
    return -dot(dir, SHADOW_CONE_AXIS[cone].xyz) >= SHADOW_CONE_AXIS[cone].w && tMax >= SHADOW_CONE_NEAREST[cone];
#else
    return mayHitSphere(origin, dir, tMax, u_sphereGeometry[i]);
#endif
}

// The lowest sphere index in the mask, taken out of it. float(bit) is exact
// (a power of two below 2^31); its exponent field is the index.
int nextCandidate(inout int candidates) {
    int bit = candidates & -candidates;
    candidates ^= bit;
    return (floatBitsToInt(float(bit)) >> 23) - 127;
}

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

// Nearest hit along `dir`; hit.t = NO_HIT when nothing is hit. `dir` is
// renormalised first: a reflected direction is unit length only to ~1e-7,
// and intersectSphere() assumes |dir| = 1 (over a chord of 8 that is 8e-6).
// Every other sphere's root comes from the exercise and is refined
// (refineRoot), so that the nearest is found among exact-as-float32 roots.
Hit closestHit(vec3 origin, vec3 dir, int leaving) {
    dir = normalize(dir);
#ifdef RL_ENVIRONMENT
    g_rayDirection = dir;  // what backgroundRadiance() sees if this ray hits nothing (environment.glsl)
#endif
    Hit hit;
    hit.t = NO_HIT;
    hit.sphere = NO_SPHERE;
    float nearest = 3.4e38;  // FLT_MAX: any real hit is nearer
    // A camera ray: the host knows the camera's side of every sphere (issue #23).
    bool fromCamera = leaving == NO_SPHERE && origin == cameraFromAnchor();
    int sphere = NO_SPHERE;
    vec4 geometry = vec4(0.0), leavingGeometry = vec4(0.0);  // centre and radius of the nearest, of `leaving`
    float anchorC = 0.0, leavingC = 0.0;            // sphereAnchorC() of the nearest, of `leaving`
    bool residual = true, leavingResidual = true;  // residualFormCandidate() of the nearest, of `leaving`
    for (int i = 0; i < sphereCount(); ++i) {
        vec4 sphereI = u_sphereGeometry[i];
#ifndef RL_CAMERA_OUTSIDE
        if (i == leaving) {
            leavingGeometry = sphereI;
#ifdef RL_SPHERE_COUNT
            leavingC = sphereAnchorC(i);
            leavingResidual = residualFormCandidate(i);
#endif
        }
#endif
        float t = intersectSphere(origin, dir, sphereI.xyz, sphereI.w);
        t = sideCheckedRoot(origin, dir, sphereI, i, t, fromCamera);  // unused for `leaving`
        // Kept if nearer, by selects: llvmpipe runs the body of an if for
        // every pixel anyway, and the selects measured 2% to 4% faster than
        // an if around these assignments (docs/performance.md).
        bool nearer = t > 0.0 && t < nearest && i != leaving;
        nearest = nearer ? t : nearest;
        sphere = nearer ? i : sphere;
        geometry = nearer ? sphereI : geometry;
#ifdef RL_SPHERE_COUNT  // unrolled: a direct load; a loop would gather it for every sphere
        float anchorCi = sphereAnchorC(i);
        bool residualI = residualFormCandidate(i);  // a constant: the residual form folds away where no sphere needs it
        anchorC = nearer ? anchorCi : anchorC;
        residual = nearer ? residualI : residual;
#endif
    }
#ifndef RL_CAMERA_OUTSIDE
    // RL_CAMERA_OUTSIDE (a program for one picture): the camera lies outside
    // every sphere and 02, 04 and 09 are the course's (the host checks both,
    // render/define_table.cpp). Then every hit is seen from outside: a camera ray
    // meets the outside of the first sphere on its way, and a mirror ray
    // leaves that outside, pushed off it, so the convex sphere it leaves is
    // never in its way again. The far root below is then never needed, and
    // its test and the selects that carry `leaving`'s data are left out.
    if (leaving != NO_SPHERE) {
        float t = leavingSphereHit(origin, dir, leavingGeometry);
        if (t > 0.0 && t < nearest) {
            nearest = t;
            sphere = leaving;
            geometry = leavingGeometry;
            anchorC = leavingC;
            residual = leavingResidual;
        }
    }
#endif
#ifndef RL_SPHERE_COUNT
    if (sphere != NO_SPHERE) {
        anchorC = sphereAnchorC(sphere);
        residual = residualFormCandidate(sphere);
    }
#endif
    if (sphere != NO_SPHERE) hit = makeHit(origin, dir, nearest, sphere, geometry, anchorC, residual);
#if defined(RL_PROBE_EXERCISE) && RL_PROBE_EXERCISE == 9
    if (g_probeCalls == 0) g_probeFirstHit = hit;
    if (g_probeCalls == 1) g_probeSecondOrigin = origin;
    ++g_probeCalls;
#endif
    return hit;
}

// Whether the segment o + t d, 0 < t < tMax (d unit), crosses the sphere's
// surface: the point of the segment nearest the centre lies within r, and
// the segment does not lie wholly inside the sphere (then it crosses no
// surface, as intersectSphere() sees it: its far root lies beyond tMax). The
// same answer as intersectSphere()'s 0 < t < tMax without a root: no square
// root, no division. RL_SEGMENT_TEST: a program for one picture whose
// 02-intersect is the course's solution (the host compares the file), so
// that a student's own intersectSphere() is what every picture of it shows.
bool segmentCrossesSphere(vec3 o, vec3 d, float tMax, vec4 sphere) {
    vec3 f = sphere.xyz - o;
    float b = dot(f, d);
    float s = clamp(b, 0.0, tMax);  // along the segment, nearest the centre
    vec3 nearest = f - s * d;
    vec3 end = f - tMax * d;
    float rr = sphere.w * sphere.w;
    return dot(nearest, nearest) <= rr && (dot(f, f) > rr || dot(end, end) > rr);
}

// Whether sphere i hides light k from o (direction d towards it) when the
// light lies on sphere i's surface or closer to it than float32 can resolve
// (lightSurfaceSphere). The model's rule (docs/model.md, "A light on a
// surface"): the sphere hides the light only where the segment crosses its
// inside before the light; a light on the surface is hidden by neither side
// of that surface. With the light's side from the host (double):
//   o inside the sphere: hidden when the light is outside it;
//   o outside: hidden when the light is inside, or when the segment passes
//   through the sphere and arrives at the light moving outward.
// No root near tMax is asked for, which float32 would round either way pixel
// by pixel (the speckle of issue #23).
bool lightNearSurfaceBlocks(vec3 o, vec3 d, vec4 sphere, int k) {
    float side = lightSurfaceSide(k);
    vec3 f = o - sphere.xyz;
    float rr = sphere.w * sphere.w;
    if (dot(f, f) < rr) return side > 0.0;
    if (side < 0.0) return true;
    float b = dot(f, d);
    vec3 perpendicular = f - b * d;
    return b < 0.0 && dot(perpendicular, perpendicular) < rr && dot(d, lightPosition(k) - sphere.xyz) > 0.0;
}

// The shadow test of sphere i on a segment: the exercise's intersectSphere(),
// or in a program for one picture with the course's 02, the test above.
// Near a huge sphere whose side the exercise's float32 cannot tell (a point
// on a small sphere resting on a ground of radius 1e4), the root from the
// anchor form decides (anchorSideRoot, issue #23). A light lying on or within
// float32's resolution of sphere i's surface is judged by the host's side of
// it (lightNearSurfaceBlocks, docs/model.md).
bool blocksSegment(vec3 o, vec3 d, float tMax, int i) {
    vec4 sphere = u_sphereGeometry[i];
    if (lightSurfaceSphere(g_shadowLight) == i) return lightNearSurfaceBlocks(o, d, sphere, g_shadowLight);
    if (refinesRoot(i)) {
        bool decided;
        float t = anchorSideRoot(o, d, sphere, sphereAnchorC(i), decided);
        if (decided) return t > 0.0 && t < tMax;
    }
#ifdef RL_SEGMENT_TEST
    return segmentCrossesSphere(o, d, tMax, sphere);
#else
    float t = intersectSphere(o, d, sphere.xyz, sphere.w);
    return t > 0.0 && t < tMax;
#endif
}

// Whether a candidate of the mask (bit b: sphere first + b) blocks the
// segment. The loop turns as often as the pixel of 8 with the most candidates needs.
bool anyCandidateBlocks(int candidates, int first, vec3 origin, vec3 dir, float tMax) {
    while (candidates != 0) {
        int i = first + nextCandidate(candidates);
        if (blocksSegment(origin, dir, tMax, i)) return true;
    }
    return false;
}

// Sphere i into its word of candidates (31 spheres a word: nextCandidate()
// reads a bit through a float's exponent, and bit 31 would be the sign).
// With i a constant, the word's choice folds.
void addCandidate(inout ivec3 words, int i, bool candidate) {
    int bit = candidate ? 1 << (i - 31 * (i / 31)) : 0;
    if (i < 31) words.x |= bit;
    else if (i < 62) words.y |= bit;
    else words.z |= bit;
}

// True when some sphere other than `leaving` is hit at 0 < t < tMax. Stops
// at the first occluder: a shadow ray needs to know only whether, not where
// (the exercise's root is not refined: it decides only against tMax). The
// sphere a shadow ray leaves is decided before, exactly (lighting.glsl,
// shadowVisibility): from outside it hides nothing the ray goes to, from
// inside it hides every light outside it.
bool anyHitBefore(vec3 origin, vec3 dir, float tMax, int leaving) {
#if defined(RL_CANDIDATE_SHADOWS) && defined(RL_SHADOW_CONES)
    // Every sphere's cone written out (RL_FOR_EACH_SPHERE(X) expands to
    // X(0) X(1) ... for the scene's spheres), so that each index is a
    // constant however long the scene's list: up to 64 spheres, 31 to a word.
    ivec3 words = ivec3(0);
#define RL_SHADOW_CANDIDATE(i) addCandidate(words, i, i != leaving && mayShadow(origin, dir, tMax, i));
    RL_FOR_EACH_SPHERE(RL_SHADOW_CANDIDATE)
    if (anyCandidateBlocks(words.x, 0, origin, dir, tMax)) return true;
#if RL_SPHERE_COUNT > 31
    if (anyCandidateBlocks(words.y, 31, origin, dir, tMax)) return true;
#endif
#if RL_SPHERE_COUNT > 62
    if (anyCandidateBlocks(words.z, 62, origin, dir, tMax)) return true;
#endif
    return false;
#elif defined(RL_CANDIDATE_SHADOWS)
    int candidates = 0;
    for (int i = 0; i < sphereCount(); ++i)
        if (i != leaving && mayShadow(origin, dir, tMax, i)) candidates |= 1 << i;
    return anyCandidateBlocks(candidates, 0, origin, dir, tMax);
#else
    for (int i = 0; i < sphereCount(); ++i)
        if (i != leaving && blocksSegment(origin, dir, tMax, i)) return true;
    return false;
#endif
}
