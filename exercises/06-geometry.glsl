// Exercise 06: the Smith / Schlick-GGX geometry term. Handout: course/06-geometry/handout.md
//
// Until you write these, there are no specular highlights.

// Schlick-GGX masking of one direction:  G1(x) = x / (x (1 - k) + k),  x = NoL or NoV.
float G1_SchlickGGX(float NoX, float k) {
    return NOT_STARTED;  // TODO
}

// Smith's separable shadowing-masking for direct light:
//     r = clamp(roughness, MIN_ROUGHNESS, 1),  k = (r + 1)^2 / 8
//     G = G1(NoV) G1(NoL)
float G_SchlickGGX(float NoV, float NoL, float roughness) {
    return NOT_STARTED;  // TODO
}
