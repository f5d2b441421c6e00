// lighting.glsl: direct light from every point light at a hit, plus ambient,
// assembled from the exercises (03 irradiance, 04 visibility, 08 BRDF).
// Returns linear radiance towards the viewer.

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
float shadowVisibility(Hit hit, vec3 lightPosition) {
    // The sphere of the hit is convex: seen from outside it shadows nothing
    // the shadow ray goes to (only lights with NoL > 0 get here); seen from
    // inside (n faces the centre) it hides every light outside it and none
    // inside. Exact, and anyHitBefore() never asks about it again.
#ifndef RL_CAMERA_OUTSIDE  // every hit seen from outside (intersect_scene.glsl, closestHit)
    vec3 centre = hit.sphereGeometry.xyz;
    float radius = hit.sphereGeometry.w;
    vec3 toLight = lightPosition - centre;
    bool inside = dot(hit.p - centre, hit.n) < 0.0;
    // A light on the surface, or closer to it than float32 resolves: its side
    // from the host (docs/model.md, "A light on a surface": not hidden).
    bool lightOutside = lightSurfaceSphere(g_shadowLight) == hit.sphere ? lightSurfaceSide(g_shadowLight) > 0.0
                                                                       : dot(toLight, toLight) > radius * radius;
    if (inside && lightOutside) return 0.0;
#endif
#ifdef RL_SINGLE_SPHERE
    return 1.0;  // specialised to a scene of one sphere: no shadow ray at all
#endif
    return lightVisibility(hit, lightPosition);
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
    if (E == vec3(0.0)) return vec3(0.0);  // facing away, or light at p: no shadow ray needed
    g_shadowLight = i;
    if (shadowVisibility(hit, lightPosition(i)) == 0.0) return vec3(0.0);
    return hitBRDF(hit, v, normalize(lightPosition(i) - hit.p), m) * E;
}

vec3 directLight(Hit hit, vec3 v, Material m) {
    vec3 radiance = vec3(0.0);
#if defined(RL_SELECT_LIGHTS)
    // Every exercise written, shadow tests unrolled (define_table.cpp): the
    // same sum, with the lights that add nothing (facing away, at p, hidden)
    // dropped by a select instead of by `continue`. llvmpipe runs every
    // light's code for all 8 pixels it shades together either way, and
    // without the branches the frame is 3% to 10% shorter (docs/performance.md).
    // A light at p makes l NaN: the select drops it.
    for (int i = 0; i < lightCount(); ++i) {
        vec3 E = pointLightIrradiance(hit.p, hit.n, lightPosition(i), lightIntensity(i));
        g_shadowLight = i;
        float visible = shadowVisibility(hit, lightPosition(i));
        vec3 f = hitBRDF(hit, v, normalize(lightPosition(i) - hit.p), m);
        bool adds = E != vec3(0.0) && visible != 0.0;
        radiance += adds ? f * E : vec3(0.0);
    }
#elif defined(RL_SHADOW_CONES)
    // Light by light, each index a constant (RL_FOR_EACH_LIGHT(X) expands to
    // X(0) X(1) ... for the scene's lights): the shadow cones of
    // intersect_scene.glsl fold into the code. A loop that holds the shadow
    // rays' candidate loop is not unrolled by the compiler.
#define RL_ADD_LIGHT(k) radiance += lightTerm(hit, v, m, k);
    RL_FOR_EACH_LIGHT(RL_ADD_LIGHT)
#else
    for (int i = 0; i < lightCount(); ++i) radiance += lightTerm(hit, v, m, i);
#endif
    return radiance;
}

// The teaching view "bounce k" keeps only the k-th surface hit (0 = primary)
// or the background seen after k bounces: shadeHit() and backgroundRadiance()
// count the calls a camera ray makes and return 0 for the others.
int g_onlyBounce = -1;  // -1: keep every bounce
int g_bounceCounter = 0;

bool keepThisBounce() {
    bool keep = g_onlyBounce < 0 || g_bounceCounter == g_onlyBounce;
    ++g_bounceCounter;
    return keep;
}

// Direct light plus the ambient term, once per hit (lit or not), plus the
// further light terms of the course's units (the extension point: a unit's
// "light" in course/*/unit.json; exercises.glsl defines unitLight()).
vec3 shadeHit(Hit hit, vec3 v) {
    if (!keepThisBounce()) return vec3(0.0);
    Material m = sphereMaterial(hit.sphere);
    vec3 radiance = directLight(hit, v, m) + u_ambient * m.albedo * m.ao;
#ifdef RL_UNIT_LIGHT
    radiance += unitLight(hit, v, m);
#endif
#ifdef RL_ENVIRONMENT
    radiance += environmentHitLight(hit, v, m);  // environment.glsl: exercise 11's approximation
#endif
    return radiance;
}

// The radiance of a ray that leaves the scene.
vec3 backgroundRadiance() {
#ifdef RL_ENVIRONMENT
    // A camera ray that misses (no hit shaded before it) sees the
    // environment; a mirror bounce that escapes adds nothing more: the
    // environment in its direction is already in the hit's environment light
    // (docs/model.md, "Environment light"; the reference does the same).
    bool cameraRay = g_bounceCounter == 0;
    if (!keepThisBounce() || !cameraRay) return vec3(0.0);
    return environmentRadiance(g_rayDirection);
#else
    return keepThisBounce() ? u_background : vec3(0.0);
#endif
}
