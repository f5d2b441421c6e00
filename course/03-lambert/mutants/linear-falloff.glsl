// mutant of: 03-lambert
// mistake: falloff with the distance, not its square
// caught by: the check's message or hint contains "not distance squared"
// Exercise 03: Lambert diffuse under a point light. Handout: course/03-lambert/handout.md

// Lambertian BRDF: a perfectly matte surface reflects albedo / pi (linear).
vec3 Fd_Lambert(vec3 albedo) {
    return albedo / PI;
}

// Irradiance at p (normal n) from a point light of intensity C I (linear),
// with inverse-square falloff and the cosine NdotL:
//     l = normalize(c - p),  d2 = |c - p|^2
//     E = (C I / d2) * clamp(dot(n, l), 0, 1)
// Zero when d2 <= 1e-12 (the light sits on p: no defined direction).
vec3 pointLightIrradiance(vec3 p, vec3 n, vec3 lightPosition, vec3 lightIntensity) {
    vec3 toLight = lightPosition - p;
    float d2 = dot(toLight, toLight);
    if (d2 <= 1e-12) return vec3(0.0);
    float NoL = clamp(dot(n, toLight * inversesqrt(d2)), 0.0, 1.0);
    return lightIntensity / sqrt(d2) * NoL;  // MUTANT: / d
}
