// Exercise 08: the Cook-Torrance BRDF, metallic workflow.
// Handout: course/08-cook-torrance/handout.md
//
// Until you write these, surfaces are lit with Lambert alone (exercise 03).
// n, v, l are unit vectors: normal, towards the viewer, towards the light.

// GGX alpha from perceptual roughness:  r = clamp(roughness, MIN_ROUGHNESS, 1),  alpha = r^2
float ggxAlpha(float roughness) {
    return NOT_STARTED;  // TODO
}

// Base reflectance:  F0 = mix(vec3(0.04), m.albedo, m.metallic)
vec3 baseReflectance(Material m) {
    return vec3(NOT_STARTED);  // TODO
}

// Specular lobe:  D G F / (4 NoL NoV),  h = normalize(l + v),
//     NoV = clamp(n.v, 1e-4, 1),  NoL = clamp(n.l, 0, 1)  (vec3(0) when NoL = 0)
//     D = D_GGX(n, h, alpha),  G = G_SchlickGGX(NoV, NoL, roughness),  F = F_Schlick(F0, v.h)
vec3 specularBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    return vec3(NOT_STARTED);  // TODO
}

// Diffuse lobe:  kd = (1 - F)(1 - metallic),  f_d = kd * Fd_Lambert(albedo)
vec3 diffuseBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    return vec3(NOT_STARTED);  // TODO
}

// The whole BRDF: diffuse + specular, and vec3(0) when n.l <= 0 (light below the horizon).
vec3 cookTorranceBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    return vec3(NOT_STARTED);  // TODO
}
