// error_bounds.glsl: where a hit point can be, and the sphere a secondary ray
// leaves. The one place that knows about float32 rounding of ray/sphere hits
// (pbrt-v4, Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed.,
// section 6.8, "Managing Rounding Error"); docs/numerics.md derives every
// bound. Exercise 04's offsetRayOrigin() turns Hit.error into the one offset.
//
// Coordinates are relative to the scene's anchor (scene.glsl; the host
// subtracts in double before float32, docs/uniforms.md), a point among the
// spheres: a hit point carries float32's rounding of the scene's size,
// whatever the scene's position in the world or the camera's distance.

// gamma_k = k u / (1 - k u), u = UNIT_ROUNDOFF (common.glsl) (Higham; pbrt-v4's gamma(n)): bounds the relative
// error of k chained roundings.
float roundingGamma(float k) { return k * UNIT_ROUNDOFF / (1.0 - k * UNIT_ROUNDOFF); }

// Whether closestHit() refines the exercise's roots on sphere i: the huge
// spheres of the scene (radius at least REFINE_RADIUS_RATIO times the
// smallest), the only ones whose |o - c|^2 - r^2 the exercise's float32
// cancels badly (app/render/scene_uniforms.cpp sets the flag; a specialised
// shader gets the set as the constant mask RL_REFINE_SPHERES, so the other
// spheres pay nothing on llvmpipe).
bool refinesRoot(int i) {
#ifdef RL_REFINE_SPHERES
    return i < 31 && ((RL_REFINE_SPHERES >> i) & 1) != 0;
#else
    return u_sphereExtra[i].w != 0.0;
#endif
}

// The exercise's root t (intersectSphere, 02) refined by one Newton step on
// g(t) = t^2 + 2 b t + C with C from sphereC(): the step converges to the
// root t is near, so every choice the exercise makes (hit or miss, near or
// far root) stands, and its position becomes what float32 must lose. Huge
// spheres near the camera need it: |o - c|^2 - r^2 in float32 keeps
// ulp(|o - c|^2) of it (1e3 for a ground of radius 1e5), which moves a hit
// 0.35 away by 1%; the step leaves t to g's rounding over |g'| = 2 |t + b|.
// The step is taken only where g rounds less than the exercise's C did,
// ~u |o - c|^2: a far small sphere (t (t + 2b) ~ |o - c|^2 cancels in g too)
// keeps the exercise's stable root.
// `sphere`: the sphere's centre and radius, `C` its |c|^2 - r^2 (sphereAnchorC).
float refineRoot(vec3 o, vec3 d, vec4 sphere, float C, float t) {
    vec3 c = sphere.xyz;
    vec3 f = o - c;
    float b = dot(f, d);
    float errorFromAnchor = abs(C) + 2.0 * dot(abs(o), abs(c)) + dot(o, o);
    float errorG = abs(t) * abs(t + 2.0 * b) + errorFromAnchor;
    if (errorG >= 0.25 * dot(f, f)) return t;
    float g = t * (t + 2.0 * b) + (C - 2.0 * dot(o, c) + dot(o, o));
    float step = g / (2.0 * (t + b));
    return abs(step) < 0.5 * abs(t) ? t - step : t;
}

// ---- The side of a sphere a ray starts on (issue #23) ----------------------------------------
//
// The exercise's c = |o - c|^2 - r^2 (02) is made of float32 numbers: o - c
// carries u (|o| + |c|) per component (each rounded from double), and the
// dot product u |o - c|^2 more. Near a huge sphere that exceeds the true
// value 2 r h (h the origin's height above the surface): a camera 1e-3
// above a ground of radius 1e5 has c = 200, float32 keeps ulp(1e10) = 1024
// of it, and the exercise sees the camera inside the ground (every ground
// pixel shaded from inside: docs/numerics.md, "Issue #23"). Where that
// happens and a better C is at hand, the framework takes the root from it.

// What the exercise's float32 |o - c|^2 - r^2 can be off by, four times over:
// 2 |f|.|rounding of f| plus the dot products' own rounding (f = o - c).
float exerciseCError(vec3 o, vec3 c, float r, vec3 f) {
    return 4.0 * UNIT_ROUNDOFF * (2.0 * dot(abs(f), abs(o) + abs(c)) + 4.0 * (dot(f, f) + r * r));
}

// The root of |o + t d - c|^2 = r^2 that a ray from o meets first (d unit),
// or NO_HIT, from C = |o - c|^2 - r^2 computed better than float32's
// |o - c|^2 - r^2: the sign of C is the side o is on, and the near root is
// C / q (no cancellation). b^2 - C is the discriminant with the smaller
// rounding near a huge sphere (b^2 ~ C there; r^2 - |f - b d|^2 would lose
// ulp(r^2)).
float rootFromC(vec3 o, vec3 d, vec3 c, float C) {
    float b = dot(o - c, d);
    float discriminant = b * b - C;
    if (discriminant < 0.0) return NO_HIT;
    float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant);
    if (q == 0.0) return NO_HIT;
    float t0 = min(C / q, q), t1 = max(C / q, q);
    return t0 > 0.0 ? t0 : t1 > 0.0 ? t1 : NO_HIT;
}

// Camera rays: |camera - centre|^2 - r^2 of sphere i, computed by the host in
// double for the camera of this frame (SceneUniformBlock::upload, every frame
// of the live view), and whether the exercise's float32 cannot tell the
// camera's side of it (then closestHit() takes the camera ray's root from it).
float cameraC(int i) { return cameraSphere(i).x; }
bool cameraSideFromHost(int i) { return cameraSphere(i).y != 0.0; }

// Secondary rays near a huge sphere (refinesRoot): C from the anchor form
// C_a - 2 o.c + |o|^2, which rounds by u (|C_a| + 2 |o|.|c| + |o|^2), small
// where o is near the anchor (a point on a small sphere resting on the
// ground). `decided`: true when the exercise's float32 cannot tell o's side
// and this C can (its rounding, 8 times over, is below |C|); then the
// result is the root from it.
float anchorSideRoot(vec3 o, vec3 d, vec4 sphere, float anchorC, out bool decided) {
    vec3 c = sphere.xyz;
    vec3 f = o - c;
    float C = anchorC - 2.0 * dot(o, c) + dot(o, o);
    float errorA = 8.0 * roundingGamma(6.0) * (abs(anchorC) + 2.0 * dot(abs(o), abs(c)) + dot(o, o));
    decided = abs(C) > errorA && abs(C) < exerciseCError(o, c, sphere.w, f);
    return decided ? rootFromC(o, d, c, C) : NO_HIT;
}

// The sphere a secondary ray leaves (its origin lies on it, pushed off by
// offsetRayOrigin): a sphere is convex, so a ray leaving its outside
// ((o - c).d >= 0) cannot hit it again, and one leaving its inside hits it
// exactly once more, at the far root -b + sqrt(b^2 - C), C ~ 0. Exact,
// whatever the offset: no self-intersection, no contact shadow or reflected
// silhouette hidden behind an offset.
// `geometry` is the sphere's centre and radius (closestHit() picks them up in
// its loop: a dynamic index into the uniform block costs a per-lane gather
// on llvmpipe, about 5% of a frame here).
float leavingSphereHit(vec3 o, vec3 d, vec4 geometry) {
    vec3 f = o - geometry.xyz;
    float b = dot(f, d);
    float far = -b + sqrt(max(b * b - (dot(f, f) - geometry.w * geometry.w), 0.0));
    return b < 0.0 ? far : NO_HIT;
}

// Whether makeHit() below can take the residual form for sphere i: a huge
// sphere near the camera. A program for one picture gets the set from the
// host, computed in double over every point of every sphere
// (RL_RESIDUAL_SPHERES, a row of
// app/render/define_table.cpp), so that a scene without such a sphere never
// computes the residual form; otherwise every sphere is a candidate and the
// smaller bound is chosen per hit.
bool residualFormCandidate(int i) {
#ifdef RL_RESIDUAL_SPHERES
    return i < 31 && ((RL_RESIDUAL_SPHERES >> i) & 1) != 0;
#else
    return true;
#endif
}

// The hit at o + t d on sphere i (`geometry`, its centre and radius, and
// `anchorC`, its |c|^2 - r^2: sphereAnchorC), taken back onto the sphere
// along its normal n = (p - c) / |p - c|, with the componentwise bound on its
// distance from the sphere (Hit.error). Two forms:
//   centre form    p' = c + r n                          (small or far spheres)
//                  e = gamma_12 (|p'| + r |n|)
//                  (c carries u |c|, r n a few u r; an error of n moves p'
//                  along the sphere, not off it)
//   residual form  p' = p - n s, s = (C - 2 p.c + |p|^2) / 2r:
//                  e = gamma_10 (|C| + 2 |p|.|c| + |p|^2) / 2r |n| + gamma_2 |p'|
//                  (a huge sphere near the anchor, where c + r n would carry
//                  ulp(|c|): 0.008 for a ground of radius 1e5)
// The residual form is taken where its bound is the smaller. docs/numerics.md
// derives both. residualCandidate: residualFormCandidate() of the sphere (a
// constant in a specialised program).
Hit makeHit(vec3 o, vec3 d, float t, int i, vec4 geometry, float anchorC, bool residualCandidate) {
    const float GAMMA_2 = 2.0 * UNIT_ROUNDOFF / (1.0 - 2.0 * UNIT_ROUNDOFF);
    const float GAMMA_10 = 10.0 * UNIT_ROUNDOFF / (1.0 - 10.0 * UNIT_ROUNDOFF);
    const float GAMMA_12 = 12.0 * UNIT_ROUNDOFF / (1.0 - 12.0 * UNIT_ROUNDOFF);
    Hit hit;
    hit.t = t;
    hit.sphere = i;
    hit.sphereGeometry = geometry;
    vec3 c = geometry.xyz;
    float r = geometry.w;
    vec3 p = o + t * d;
    // Where float32 cannot place p apart from the centre (a sphere smaller
    // than the rounding of o + t d: radius 1 seen from 1e10, or hit at t ~
    // 1e15 inside a huge sphere), p - c rounds to 0 and normalize() would be
    // 0/0, NaN in every term after it (issue #23). Then the hit faces the ray.
    vec3 fromCentre = p - c;
    vec3 n = dot(fromCentre, fromCentre) > 0.0 ? normalize(fromCentre) : -d;
    vec3 an = abs(n);
    hit.p = c + r * n;
    hit.error = GAMMA_12 * (abs(hit.p) + r * an);
    if (residualCandidate) {
        float pp = dot(p, p);
        float halfInverseRadius = 0.5 / r;
        float step = (anchorC - 2.0 * dot(p, c) + pp) * halfInverseRadius;
        // The step is (|p - c| - r)(1 + (|p - c| - r) / 2r): first order in p's
        // distance from the sphere. Its second-order part, step^2 / 2r, is
        // negligible where the root was refined (p on the sphere to float32),
        // not where p carries the rounding of a far origin (t ~ 1e5 r: p off
        // by 1e-2 r, the residual form 1e-4 r inside the sphere, which
        // pbrt's re-intersection test caught, tests/metamorphic/test_reintersect.cpp):
        // step^2 / r bounds it twice over.
        float residualError = GAMMA_10 * (abs(anchorC) + 2.0 * dot(abs(p), abs(c)) + pp) * halfInverseRadius +
                              step * step * 2.0 * halfInverseRadius;
        if (residualError < GAMMA_12 * (maxAbs(c) + 2.0 * r)) {  // |p'| + r <= |c| + 2r
            hit.p = p - n * step;
            hit.error = residualError * an + GAMMA_2 * abs(hit.p);
        }
    }
    hit.n = dot(n, d) > 0.0 ? -n : n;  // hit from inside: face the ray
    return hit;
}
