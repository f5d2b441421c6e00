// views.glsl: the teaching views of `raylab view` (number keys) and
// `raylab render --view NAME`, documented in docs/lecture.md. Each shows one
// quantity at the primary hit, computed by the same exercise functions as the
// final image. Term views use the scene's first light (the key light).

uniform int u_view;        // one of the VIEW_ constants
uniform int u_viewBounce;  // for VIEW_BOUNCE: 0 = primary hit, 1 = first reflection, ...

// A scene with model variants shows its own D, G, F and lobes (model_variants.glsl).
const int VIEW_FINAL = 0;     // the picture
const int VIEW_D = 1;         // GGX D, shown as D / (1 + D)
const int VIEW_G = 2;         // Smith G
const int VIEW_F = 3;         // Schlick F(v.h) of the key light (rgb), log display (fresnelDisplay)
const int VIEW_DIFFUSE = 4;   // diffuse radiance of all lights (through the display step)
const int VIEW_SPECULAR = 5;  // specular radiance of all lights (through the display step)
const int VIEW_NDOTL = 6;     // n.l of the key light
const int VIEW_SHADOW = 7;    // 1 where the key light is visible, 0 in its shadow
const int VIEW_NORMALS = 8;   // n * 0.5 + 0.5
const int VIEW_BOUNCE = 9;    // the contribution of bounce u_viewBounce alone
const int VIEW_F_NOV = 10;    // F(n.v) = F_SchlickRoughness: the mirror bounce's weight (rgb), log display
// Environment light's approximation (issue 24, environment.glsl); black without an environment:
const int VIEW_ENV_IRRADIANCE = 11;   // E(n) / pi from the nine SH coefficients (through the display step)
const int VIEW_ENV_PREFILTERED = 12;  // the prefiltered environment towards r at the roughness's level (display step)
const int VIEW_ENV_SCALE = 13;        // the split-sum table's scale at (n.v, roughness)
const int VIEW_ENV_BIAS = 14;         // the split-sum table's bias at (n.v, roughness)

// The F views show log10(F) from 0.01 (black) to 1 (white): a dielectric's
// 0.04 is 0.30 (visible on a projector), the grazing rim reaches 1. The
// window's colour bar (app/view/view_caption.cpp) labels the same mapping.
vec3 fresnelDisplay(vec3 F) {
    const float kLowest = 0.01;  // two decades: below 1% nothing reflects visibly
    return clamp(log(max(F, vec3(kLowest))) / log(10.0) / 2.0 + 1.0, 0.0, 1.0);
}

// Linear values in [0, 1] for the term views (radiance views are handled by
// main() through the display step).
vec3 teachingView(vec3 origin, vec3 dir) {
    Hit hit = closestHit(origin, dir, NO_SPHERE);
    if (hit.t == NO_HIT) return vec3(0.0);
    if (u_view == VIEW_NORMALS) return hit.n * 0.5 + 0.5;
    vec3 v = -dir;
    Material m = sphereMaterial(hit.sphere);
    if (u_view >= VIEW_ENV_IRRADIANCE) {
#ifdef RL_ENVIRONMENT
        // The terms environmentHitLight() combines, each on its own: what a
        // white Lambert surface reflects of the SH9 irradiance, the
        // prefiltered radiance the specular lobe reads, and the table's
        // scale and bias that weigh it (exercise 11's functions).
        if (u_view == VIEW_ENV_IRRADIANCE) return u_envIntensity * shIrradiance(environmentLocal(hit.n)) / PI;
        if (u_view == VIEW_ENV_PREFILTERED) {
            vec3 r = environmentLocal(reflect(-v, hit.n));
            return u_envIntensity * prefilteredRadiance(r, prefilteredLevel(m.roughness, u_envLevels));
        }
        vec2 scaleBias = splitSumLookup(clamp(dot(hit.n, v), 1e-4, 1.0), m.roughness);
        return vec3(u_view == VIEW_ENV_SCALE ? scaleBias.x : scaleBias.y);
#else
        return vec3(0.0);  // no environment in this scene
#endif
    }
    if (u_view == VIEW_DIFFUSE || u_view == VIEW_SPECULAR) {
        vec3 sum = vec3(0.0);
        for (int i = 0; i < lightCount(); ++i) {
            vec3 E = pointLightIrradiance(hit.p, hit.n, lightPosition(i), lightIntensity(i));
            if (E == vec3(0.0)) continue;
            if (shadowVisibility(hit, lightPosition(i)) == 0.0) continue;
            vec3 l = normalize(lightPosition(i) - hit.p);
#ifdef RL_MODEL_VARIANTS  // the lobes of the scene's model (model_variants.glsl), once 08 is started
            vec3 edgeTint = sphereEdgeTint(hit.sphere);
            vec3 f = (u_view == VIEW_DIFFUSE) ? modelDiffuseBRDF(hit.n, v, l, m, edgeTint)
                                              : modelSpecularBRDF(hit.n, v, l, m, edgeTint);
#else
            vec3 f = (u_view == VIEW_DIFFUSE) ? diffuseBRDF(hit.n, v, l, m) : specularBRDF(hit.n, v, l, m);
#endif
            sum += f * E;
        }
        return sum;
    }
    if (lightCount() == 0) return vec3(0.0);
    vec3 l = normalize(lightPosition(0) - hit.p);
    vec3 h = normalize(l + v);
    float NoL = clamp(dot(hit.n, l), 0.0, 1.0);
    float NoV = clamp(dot(hit.n, v), 1e-4, 1.0);
    if (u_view == VIEW_NDOTL) return vec3(NoL);
    if (u_view == VIEW_SHADOW) {
        return vec3(shadowVisibility(hit, lightPosition(0)));
    }
    if (u_view == VIEW_D) {
#ifdef RL_MODEL_VARIANTS
        float D = modelD(hit.n, h, ggxAlpha(m.roughness));  // the scene's D (GGX under Blinn-Phong)
#else
        float D = D_GGX(hit.n, h, ggxAlpha(m.roughness));
#endif
        return vec3(D / (1.0 + D));
    }
    if (u_view == VIEW_G) {
#ifdef RL_MODEL_VARIANTS
        float G = modelG(NoV, NoL, m.roughness);
#else
        float G = G_SchlickGGX(NoV, NoL, m.roughness);
#endif
        return vec3(G);
    }
    if (u_view == VIEW_F || u_view == VIEW_F_NOV) {
        // F(v.h) weighs the highlight of the key light and does not depend on
        // n; F(n.v) is the throughput factor of the mirror bounce (exercise
        // 09, every model variant) and brightens towards the rims.
        if (u_view == VIEW_F_NOV) {
            vec3 Fr = F_SchlickRoughness(baseReflectance(m), NoV, m.roughness);
            return fresnelDisplay(Fr);
        }
#ifdef RL_MODEL_VARIANTS
        vec3 F = modelF(baseReflectance(m), sphereEdgeTint(hit.sphere), dot(v, h));
#else
        vec3 F = F_Schlick(baseReflectance(m), dot(v, h));
#endif
        return fresnelDisplay(F);
    }
    return vec3(0.0);
}

bool viewIsRadiance() {
    return u_view == VIEW_FINAL || u_view == VIEW_BOUNCE || u_view == VIEW_DIFFUSE || u_view == VIEW_SPECULAR ||
           u_view == VIEW_ENV_IRRADIANCE || u_view == VIEW_ENV_PREFILTERED;
}
