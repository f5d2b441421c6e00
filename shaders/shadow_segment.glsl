// shadow_segment.glsl: whether a segment crosses one sphere, exactly, for
// any segment (the generic program's shadow test, and a specialised
// program's for the pairs of light and sphere the light's side cannot
// decide: shadow_light_side.glsl). A shadow ray needs whether, not where,
// so no root is taken where none is needed.

// Whether the segment o + t d, 0 < t < tMax (d unit), crosses the sphere's
// surface: the point of the segment nearest the centre lies within r, and
// the segment does not lie wholly inside the sphere (then it crosses no
// surface: intersectSphere()'s far root lies beyond tMax). No square root,
// no division.
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

// The shadow test of sphere i on a segment. Near a huge sphere whose side
// float32 cannot tell (a point on a small sphere resting on a ground of
// radius 1e4), the root from the anchor form decides (anchorSideRoot, issue
// #23). A light lying on or within float32's resolution of sphere i's
// surface is judged by the host's side of it (lightNearSurfaceBlocks).
// `light`: the light the segment goes to (-1: none known).
bool blocksSegment(vec3 o, vec3 d, float tMax, int i, int light) {
    vec4 sphere = sphereGeometry(i);
    if (lightSurfaceSphere(light) == i) return lightNearSurfaceBlocks(o, d, sphere, light);
    if (refinesRoot(i)) {
        bool decided;
        float t = anchorSideRoot(o, d, sphere, sphereAnchorC(i), decided);
        if (decided) return t > 0.0 && t < tMax;
    }
    return segmentCrossesSphere(o, d, tMax, sphere);
}
