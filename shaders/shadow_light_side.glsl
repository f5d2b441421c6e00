// shadow_light_side.glsl: the shadow test from the light's side, for a
// program specialised to one scene (RL_SHADOW_STEPS, RL_LIGHT_OCCLUDERS:
// rows of app/render/define_table.cpp).
//
// For a light L outside sphere (c, r) the host computes in double, per pair
// of light k and sphere j, w = L - c and C = |L - c|^2 - r^2. The segment
// from o to L, with u = L - o, d2 = |u|^2 and E = w.u, crosses the sphere iff
//     E > 0  and  E^2 >= d2 C  and  (E < d2  or  |c - o|^2 - r^2 <= 0),
// where |c - o|^2 - r^2 = d2 - 2 E + C: the line from L through o passes
// within r of c, on o's side of L, and the sphere's near side lies between o
// and L, or o is inside it. No square root, no division, one dot product per
// sphere against a constant, and exact for every o.
//
// It answers for the segment from o to the light; the exercise asks about
// its own segment (04's lightVisibility: o, a direction, a length). Where
// that segment does not end at the light within float32's rounding, the
// answer would be the model's, not the exercise's: the pixel is marked
// (g_assumptionBroken) and drawn again by the generic program
// (render/gl_renderer.h), so that what shows is what the exercise asked.

// Set where a specialised program's assumption about the exercise files
// did not hold at this pixel: main.frag marks the pixel, and the host draws
// it again with the generic program.
bool g_assumptionBroken = false;

// The segment's end within 1e-5 of its length from the light: 04 written
// the model's way ends it there to a few float32 roundings (1e-7); a mistake
// (an unbounded or shortened ray, an unnormalised direction) misses by far more.
bool segmentEndsAtLight(vec3 o, vec3 d, float tMax, vec3 light, float d2) {
    vec3 miss = o + tMax * d - light;
    return dot(miss, miss) <= 1e-10 * d2;
}

#ifdef RL_SHADOW_STEPS
// vec4(L - c, |L - c|^2 - r^2) of light k and sphere j at k * RL_SPHERE_COUNT + j.
const vec4 LIGHT_OCCLUDERS[] = RL_LIGHT_OCCLUDERS;

// Whether the sphere of `w` (LIGHT_OCCLUDERS) blocks the segment from o to
// its light (u = L - o, d2 = |u|^2).
bool lightSideBlocks(vec4 w, vec3 u, float d2) {
    float E = dot(w.xyz, u);
    return E > 0.0 && E * E >= d2 * w.w && (E < d2 || d2 - 2.0 * E + w.w <= 0.0);
}
#endif
