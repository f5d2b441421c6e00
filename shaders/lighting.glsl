// lighting.glsl: the light a hit sends towards the viewer (docs/model.md,
// "Direct light"): every point light through the exercises (03 irradiance,
// 04 visibility, 08 BRDF), plus the ambient term, the course units' light
// terms and the environment's. Linear radiance.

// The BRDF: exercise 08's Cook-Torrance.
vec3 surfaceBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    return cookTorranceBRDF(n, v, l, m);
}

#ifdef RL_MODEL_VARIANTS
// A scene with model variants: modelBRDF() (model_variants.glsl) in place of
// 08's cookTorranceBRDF(); its conductor Fresnel needs the sphere's edge tint.
vec3 surfaceBRDF(vec3 n, vec3 v, vec3 l, Material m, vec3 edgeTint) {
    return modelBRDF(n, v, l, m, edgeTint);
}
#endif

// Whether the light at lightPosition reaches the hit: exercise 04's shadow ray.
// The sphere of the hit is convex: seen from outside it shadows nothing the
// shadow ray goes to (only lights with n.l > 0 add light); seen from inside
// (n faces the centre) it hides every light outside it and none inside.
// Exact, and anyHitBefore() never asks about it again.
float shadowVisibility(Hit hit, vec3 lightPosition) {
    vec3 centre = hit.sphereGeometry.xyz;
    float radius = hit.sphereGeometry.w;
    vec3 toLight = lightPosition - centre;
    bool inside = dot(hit.p - centre, hit.n) < 0.0;
    // A light on the surface, or closer to it than float32 resolves: its side
    // from the host (docs/model.md, "A light on a surface": not hidden).
    bool lightOutside = lightSurfaceSphere(g_shadowLight) == hit.sphere ? lightSurfaceSide(g_shadowLight) > 0.0
                                                                       : dot(toLight, toLight) > radius * radius;
    if (inside && lightOutside) return 0.0;
#ifdef RL_SINGLE_SPHERE
    return 1.0;  // specialised to a scene of one sphere: no shadow ray at all
#endif
    return lightVisibility(hit, lightPosition);
}

// The visibility of light i from the hit: the shadow ray knows its light
// (g_shadowLight: intersect_scene.glsl tests it from the light's side in a
// program specialised to the scene), and no other call of anyHitBefore()
// is taken for it.
float lightShadow(Hit hit, int i) {
    g_shadowLight = i;
    float visible = shadowVisibility(hit, lightPosition(i));
    g_shadowLight = -1;
    return visible;
}

// The BRDF at the hit towards the light in direction l (with the sphere's
// edge tint in a scene of model variants).
vec3 hitBRDF(Hit hit, vec3 v, vec3 l, Material m) {
#ifdef RL_MODEL_VARIANTS
    return surfaceBRDF(hit.n, v, l, m, sphereEdgeTint(hit.sphere));
#else
    return surfaceBRDF(hit.n, v, l, m);
#endif
}

// What light i adds at the hit: nothing where it faces away, sits at p or is hidden.
vec3 lightTerm(Hit hit, vec3 v, Material m, int i) {
    vec3 E = pointLightIrradiance(hit.p, hit.n, lightPosition(i), lightIntensity(i));
#ifdef RL_EXERCISES_FINISHED
    // Every exercise written: the light that adds nothing is dropped by a
    // select, not a branch. llvmpipe runs every light's code for all 8 pixels
    // it shades together either way, and without the branches the frame is
    // 3% to 10% shorter (docs/performance.md). A light at p makes l NaN: the
    // select drops it. With a stub, the branch keeps a shadow ray from being
    // asked where the light adds nothing.
    float visible = lightShadow(hit, i);
    vec3 f = hitBRDF(hit, v, normalize(lightPosition(i) - hit.p), m);
    return E != vec3(0.0) && visible != 0.0 ? f * E : vec3(0.0);
#else
    if (E == vec3(0.0)) return vec3(0.0);  // facing away, or light at p: no shadow ray needed
    if (lightShadow(hit, i) == 0.0) return vec3(0.0);
    return hitBRDF(hit, v, normalize(lightPosition(i) - hit.p), m) * E;
#endif
}

vec3 directLight(Hit hit, vec3 v, Material m) {
    vec3 radiance = vec3(0.0);
#ifdef RL_FOR_EACH_LIGHT
    // Light by light, each index a constant (RL_FOR_EACH_LIGHT(X) expands to
    // X(0) X(1) ... for the scene's lights): the light's numbers and its
    // shadow tests fold into the code.
#define RL_ADD_LIGHT(k) radiance += lightTerm(hit, v, m, k);
    RL_FOR_EACH_LIGHT(RL_ADD_LIGHT)
#else
    for (int i = 0; i < lightCount(); ++i) radiance += lightTerm(hit, v, m, i);
#endif
    return radiance;
}

// Everything a hit sends towards the viewer: direct light plus the ambient
// term, once per hit (lit or not), plus the further light terms of the
// course's units (the extension point: a unit's "light" in course/*/unit.json;
// exercises.glsl defines unitLight()) and the environment's.
vec3 hitRadiance(Hit hit, vec3 v) {
    Material m = sphereMaterial(hit.sphere);
    vec3 radiance = directLight(hit, v, m) + ambientFactor() * m.albedo * m.ao;
#ifdef RL_UNIT_LIGHT
    radiance += unitLight(hit, v, m);
#endif
#ifdef RL_ENVIRONMENT
    radiance += environmentHitLight(hit, v, m);  // environment.glsl: exercise 11's approximation
#endif
    return radiance;
}

// What a ray that leaves the scene brings back. With an environment, a
// camera ray that misses sees the environment; a mirror bounce that escapes
// adds nothing more: the environment in its direction is already in the
// hit's environment light (docs/model.md, "Environment light"; the
// reference does the same). `cameraRay`: no hit was shaded before it.
vec3 missRadiance(bool cameraRay) {
#ifdef RL_ENVIRONMENT
    return cameraRay ? environmentRadiance(g_rayDirection) : vec3(0.0);
#else
    return backgroundColour();
#endif
}
