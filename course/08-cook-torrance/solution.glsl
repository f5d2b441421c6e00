// Exercise 08: the Cook-Torrance BRDF, metallic workflow. Handout: course/08-cook-torrance/handout.md

// GGX alpha from perceptual roughness: r = clamp(roughness, MIN_ROUGHNESS, 1),
// alpha = r^2. The lower clamp keeps D finite for mirror-like surfaces.
float ggxAlpha(float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    return r * r;
}

// Reflectance at normal incidence: 4% for dielectrics, the albedo for metals.
//     F0 = mix(vec3(0.04), albedo, metallic)
vec3 baseReflectance(Material m) {
    return mix(vec3(0.04), m.albedo, m.metallic);
}

// Specular lobe:  D G F / (4 NoL NoV), NoV = clamp(n.v, 1e-4, 1), NoL = clamp(n.l, 0, 1).
vec3 specularBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    if (NoL == 0.0) return vec3(0.0);
    float NoV = clamp(dot(n, v), 1e-4, 1.0);  // 1e-4: keeps 1/NoV finite at grazing view
    vec3 h = normalize(l + v);
    float D = D_GGX(n, h, ggxAlpha(m.roughness));
    float G = G_SchlickGGX(NoV, NoL, m.roughness);
    vec3 F = F_Schlick(baseReflectance(m), dot(h, v));
    return D * G * F / (4.0 * NoL * NoV);
}

// Diffuse lobe: what the specular reflection leaves, and nothing for metals.
//     kd = (1 - F)(1 - metallic),  f_d = kd albedo / pi
vec3 diffuseBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    vec3 h = normalize(l + v);
    vec3 F = F_Schlick(baseReflectance(m), dot(h, v));
    vec3 kd = (1.0 - F) * (1.0 - m.metallic);
    return kd * Fd_Lambert(m.albedo);
}

// The whole BRDF f(l, v): diffuse + specular (linear, per steradian), and
// nothing for a light below the horizon (n.l <= 0).
vec3 cookTorranceBRDF(vec3 n, vec3 v, vec3 l, Material m) {
    if (dot(n, l) <= 0.0) return vec3(0.0);
    return diffuseBRDF(n, v, l, m) + specularBRDF(n, v, l, m);
}
