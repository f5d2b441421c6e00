// Exercise 03: Lambert diffuse under a point light. Handout: course/03-lambert/handout.md
//
// Until you write these, surfaces receive no direct light (ambient only).

// The Lambertian BRDF (linear colour, per steradian):  f_d = albedo / pi
vec3 Fd_Lambert(vec3 albedo) {
    return vec3(NOT_STARTED);  // TODO
}

// Irradiance at p (unit normal n) from a point light at lightPosition with
// intensity lightIntensity = C I (linear). Contract:
//     l = normalize(lightPosition - p),  d2 = |lightPosition - p|^2
//     E = (C I / d2) * clamp(dot(n, l), 0, 1)
// and vec3(0) when d2 <= 1e-12 (the light sits on p).
vec3 pointLightIrradiance(vec3 p, vec3 n, vec3 lightPosition, vec3 lightIntensity) {
    return vec3(NOT_STARTED);  // TODO
}
