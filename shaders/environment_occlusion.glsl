// environment_occlusion.glsl: the spheres' shadow in the environment light
// (issue 34; docs/model.md, "Environment light", "Occlusion by the spheres"),
// compiled in with RL_ENV_OCCLUSION (app/render/define_table.cpp; its value
// picks the strategy, the bench's env:occlusion=... rows sweep it):
//   1  caps:             E and P each times the share of their lobe no sphere covers
//   2  caps, directional: the diffuse part loses what the covered directions
//                         would bring (each cap's mean radiance, from the
//                         host's cap chain), the specular part as in 1
// Each other sphere (centre c, radius R) seen from the hit point p covers a
// cap of directions: axis w = (c - p) / d, d = |c - p|, half-angle
// asin(R / d). The reference's V(p, l) is 0 inside a cap, 1 outside: the
// light a covered direction would bring is lost (no light of its own: a
// mirror bounce that meets the sphere adds that sphere's light, as before).
// Included by environment.glsl after the lookups it uses.

// ---- the model's constants, in one place --------------------------------------------
// The specular lobe as a cone around r = reflect(-v, n): the cone that holds
// all but ENV_CONE_ENERGY of a Phong lobe of the same width (exponent
// 2 / alpha^2 - 2, alpha = roughness^2): cos(a) = ENV_CONE_ENERGY^(1 / (exponent + 1)).
const float ENV_CONE_ENERGY = 0.244;
// A cap's mean radiance is read over the part of it nearest n (the cosine's
// weight): a cap inside it, moved towards n by at most this share of its half-angle.
const float ENV_CAP_SHIFT = 0.5;
// Where a larger cap holds the share phi of a cap's weight, the cap's mean is
// read over the part left to it: its centre moved away from the shared lens
// by ENV_LENS_AWAY * phi of its half-angle, the half-angle shrunk by
// ENV_LENS_SHRINK * phi (measured on the four scenes of docs/performance.md,
// "Occlusion by the spheres": the studio's white sphere facing the copper
// one, whose cap dips into the ground's under the horizon).
const float ENV_LENS_AWAY = 1.0;
const float ENV_LENS_SHRINK = 0.3;

// The host's cap chain (app/render/environment_caps.h, whose constants they
// are): level k averages the map over caps of half-angle
// b_k = u_envSmallestCap * 2^(k/2), k < u_envCapLevels; the layers of one
// volume hold each level's integral over its cap (mean times 1 - cos b_k),
// resampled to one size and divided by u_envCapScale
// (app/render/environment_resources.h, capVolume).
uniform highp sampler3D u_envCaps;
uniform int u_envCapLevels;
uniform float u_envCapScale;
uniform float u_envSmallestCap;
// The map's sun (u_envSun, environment.glsl) is left out of the cap chain:
// it is shadowed as a disc, every cap that covers part of it taking that
// part (coneCapCoverage), so its shadow has its own penumbra.

// The map's mean radiance (no intensity) over the cap of half-angle b around
// the image-frame direction w: one trilinear lookup, bilinear in each level
// as every lookup of the map, the two levels' integrals around b mixed
// linearly in log2 of the angle (two levels an octave), over the cap's own
// 1 - cos b; so a bright spot inside both counts in full, one between their
// edges in part.
vec3 capMeanRadiance(vec3 w, float b) {
    float l = clamp(2.0 * log2(max(b, 1e-6) / u_envSmallestCap), 0.0, float(u_envCapLevels - 1));
    vec3 integral = u_envCapScale * texture(u_envCaps, vec3(equirectUv(w), (l + 0.5) / float(u_envCapLevels))).rgb;
    return integral / max(1.0 - cos(b), 1e-7);
}

// The share of the cosine-weighted hemisphere of n that a sphere covers
// (its form factor, clipped by the horizon) is exercise 12's
// sphereFormFactor(p, n, centre, radius) (course/12-sky-shadows).

// The share of a cone of half-angle a that a cap of half-angle b covers, their
// axes theta apart (Oat and Sander 2007, "Ambient aperture lighting": the
// smaller cap's area, faded by a smoothstep between the two tangencies).
// (1 - cos a and 1 - cos b given, as the callers have them.)
float coneCapCoverage(float a, float oneMinusCosA, float b, float oneMinusCosB, float theta) {
    if (theta >= a + b) return 0.0;
    float overlap = theta <= abs(a - b) ? 1.0 : smoothstep(0.0, 1.0, 1.0 - (theta - abs(a - b)) / (a + b - abs(a - b)));
    return overlap * min(oneMinusCosA, oneMinusCosB) / max(oneMinusCosA, 1e-7);
}

// The two largest caps seen from the current hit (not its own sphere's, nor
// one around p), found once per hit (capsSeenFrom): xyz the axis
// w = (c - p) / d, w the sine of the half-angle R / d (-1 where there is
// none); and their spheres' indices (-1). A cap's shared part is taken from
// these two only (capShareNotCovered): one pass over the spheres, not one per
// cap, and no array indexed per pixel (llvmpipe spills those). The smaller
// caps' overlaps among themselves are left out (docs/decisions.md,
// "Overlaps with the two largest caps only", has the measurements).
vec4 g_bigCap[2];
int g_big[2];
void capsSeenFrom(vec3 p, int own) {
    g_big[0] = -1; g_big[1] = -1;
    g_bigCap[0] = vec4(0.0, 0.0, 0.0, -1.0); g_bigCap[1] = g_bigCap[0];
    for (int j = 0; j < sphereCount(); ++j) {
        vec4 o = sphereGeometry(j);
        vec3 q = o.xyz - p;
        float d = length(q);
        float sinB = o.w / d;
        if (j == own || sinB >= 1.0) continue;
        vec4 cap = vec4(q / d, sinB);
        if (sinB > g_bigCap[0].w) { g_bigCap[1] = g_bigCap[0]; g_big[1] = g_big[0]; g_bigCap[0] = cap; g_big[0] = j; }
        else if (sinB > g_bigCap[1].w) { g_bigCap[1] = cap; g_big[1] = j; }
    }
}

// The share of sphere i's cap (axis w, half-angle b given by its sine sb and
// cosine cb, form factor F seen from the hit) that no larger cap of another
// sphere holds: where caps overlap, the larger one takes the shared
// directions and the smaller one only what is its own, so the light of a
// direction is taken out once. The shared part's cosine weight is its solid
// angle times n.m, m the middle of the shared lens on the great circle
// through both axes; `lens` is the sum of the lenses' middles times their
// weights (where the shared part lies). Only the two largest caps are
// looked at (capsSeenFrom).
float capShareNotCovered(int i, vec3 w, float sb, float cb, float F, Hit hit, out vec3 lens) {
    lens = vec3(0.0);
    if (F <= 0.0) return 1.0;
    float shared = 0.0;
    for (int k = 0; k < 2; ++k) {
        int j = k == 0 ? g_big[0] : g_big[1];
        vec4 cap = k == 0 ? g_bigCap[0] : g_bigCap[1];
        if (j < 0 || j == i) continue;
        float sbj = cap.w;  // sin of its half-angle
        // Not larger (equal ones by index): skipped. (A sphere holding p is
        // never one of the two: capsSeenFrom leaves it out.)
        if (sbj < sb || (sbj == sb && j > i)) continue;
        vec3 wj = cap.xyz;
        float cbj = sqrt(1.0 - sbj * sbj);
        float cg = dot(w, wj);
        if (cg <= cb * cbj - sb * sbj) continue;  // apart: g >= b + bj
        // The shared lens spans, on the great circle from w towards wj, the
        // angles lo to b: lo = -b where the larger cap holds the whole of
        // this one (g <= bj - b), else g - bj; b, as g + bj >= b. Its middle m
        // is the sum of its two ends' directions: no angle is needed.
        vec3 e = wj - cg * w;
        float sg = length(e);
        e = sg > 1e-6 ? e / sg : vec3(0.0);
        bool reachesPastW = cg >= cbj * cb + sbj * sb;  // g <= bj - b: the larger cap holds the smaller one
        float cosLo = reachesPastW ? cb : cg * cbj + sg * sbj;
        float sinLo = reachesPastW ? -sb : sg * cbj - cg * sbj;
        vec3 m = normalize((cosLo + cb) * w + (sinLo + sb) * e);
        // Its solid angle: the smaller cap's, faded by a smoothstep in cos(g)
        // between the two tangencies (Oat and Sander 2007's overlap, in cosines).
        float t = (cg - (cb * cbj - sb * sbj)) / max(2.0 * sb * sbj, 1e-7);
        float weight = 2.0 * PI * (1.0 - cb) * smoothstep(0.0, 1.0, t) * max(dot(hit.n, m), 0.0);
        shared += weight;
        lens += weight * m;
    }
    return clamp(1.0 - shared / (PI * F), 0.0, 1.0);
}

// The specular cone's half-angle for perceptual roughness.
float specularConeAngle(float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    float alpha = r * r;
    float exponent = 2.0 / (alpha * alpha) - 2.0;
    return acos(pow(ENV_CONE_ENERGY, 1.0 / (exponent + 1.0)));
}

// The environment light a hit keeps with the spheres' caps taken out:
// irradiance E (world, with intensity) and prefiltered radiance P towards r
// (world), both as environmentHitLight() read them.
struct OccludedLight {
    vec3 irradiance;
    vec3 prefiltered;
    float sun;  // the share of the sun's disc no sphere covers
};

OccludedLight occludeEnvironment(Hit hit, vec3 reflected, float roughness, vec3 E, vec3 P) {
#if RL_ENV_OCCLUSION == 2
    capsSeenFrom(hit.p, hit.sphere);
#endif
    float coneAngle = specularConeAngle(roughness);
    float coneOneMinusCos = 1.0 - cos(coneAngle);
    float sunOneMinusCos = 1.0 - cos(u_envSun.w);
    vec3 r = reflected;
    float diffuseVisible = 1.0, specularVisible = 1.0;
    vec3 lost = vec3(0.0);
    float sunVisible = 1.0;
    for (int i = 0; i < sphereCount(); ++i) {
        if (i == hit.sphere) continue;  // its own sphere hides only what lies below the horizon
        vec4 s = sphereGeometry(i);
        vec3 toCentre = s.xyz - hit.p;
        float d = length(toCentre);
        vec3 w = toCentre / d;
        float h = d / s.w;
        if (h <= 1.0) {  // inside that sphere: every direction covered
            diffuseVisible = 0.0;
            specularVisible = 0.0;
            lost = E;
            continue;
        }
        float F = sphereFormFactor(hit.p, hit.n, s.xyz, s.w);  // exercise 12
        float capAngle = asin(1.0 / h);
        float cb = sqrt(1.0 - 1.0 / (h * h));  // cos(capAngle)
        float S = coneCapCoverage(coneAngle, coneOneMinusCos, capAngle, 1.0 - cb, acos(clamp(dot(r, w), -1.0, 1.0)));
        specularVisible *= 1.0 - clamp(S, 0.0, 1.0);
#if RL_ENV_OCCLUSION == 2
        if (F != 0.0) {  // a negative F (a mistake of exercise 12) shows as light added, as it would compute
            // The cosine weights the cap towards n: its mean is read over the
            // cap inside it nearest n, its centre moved towards the
            // cosine-weighted centroid (by at most half the cap).
            float along = 2.0 * (1.0 - cb * cb * cb) / 3.0 * max(dot(hit.n, w), 0.0);
            vec3 side = hit.n - dot(hit.n, w) * w;
            float across = (1.0 - cb) - (1.0 - cb * cb * cb) / 3.0;
            float shift = min(atan(across * length(side), along), ENV_CAP_SHIFT * capAngle);
            vec3 centre = normalize(w + tan(shift) * (length(side) > 1e-6 ? normalize(side) : vec3(0.0)));
            vec3 lens;
            float share = capShareNotCovered(i, w, 1.0 / h, cb, F, hit, lens);
            float radius = capAngle - shift;
            // Where a larger cap holds the share phi of this one's weight, its
            // mean is read over the part the lenses leave: the read turned away
            // from them by ENV_LENS_AWAY phi of its half-angle (a rotation by
            // its sine and cosine), its half-angle times 1 - ENV_LENS_SHRINK phi.
            float phi = 1.0 - share;
            vec3 away = centre - lens;
            away -= dot(away, centre) * centre;
            float awayLength = length(away);
            float turn = ENV_LENS_AWAY * phi * radius;
            if (awayLength > 1e-6) centre = cos(turn) * centre + sin(turn) * (away / awayLength);
            radius *= 1.0 - ENV_LENS_SHRINK * phi;
            lost += PI * F * share * u_envIntensity * capMeanRadiance(environmentLocal(centre), radius);
        }
        float sunCos = dot(u_envSun.xyz, w);
        if (u_envSun.w > 0.0 && sunCos > cos(capAngle + u_envSun.w))  // the sun's disc reaches into the cap
            sunVisible *= 1.0 - clamp(coneCapCoverage(u_envSun.w, sunOneMinusCos, capAngle, 1.0 - cb, acos(clamp(sunCos, -1.0, 1.0))), 0.0, 1.0);
#else
        diffuseVisible *= 1.0 - F;
#endif
    }
    OccludedLight o;
#if RL_ENV_OCCLUSION == 2
    o.sun = sunVisible;
#else
    o.sun = diffuseVisible;
#endif
    o.irradiance = max(E * diffuseVisible - lost, vec3(0.0));
    o.prefiltered = P * specularVisible;
    return o;
}
