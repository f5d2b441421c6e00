// mutant of: 06-geometry
// mistake: the image-based-lighting k = alpha/2 used for direct light
// caught by: the check's message or hint contains "image-based-lighting"
// Exercise 06: the Smith / Schlick-GGX geometry term. Handout: course/06-geometry/handout.md

// Schlick-GGX masking for one direction x (Karis 2013, "Real Shading in
// Unreal Engine 4"):  G1(x) = x / (x (1 - k) + k),  x = n.l or n.v.
float G1_SchlickGGX(float NoX, float k) {
    return NoX / (NoX * (1.0 - k) + k);
}

// Smith's separable form for direct light: G = G1(NoV) G1(NoL), with
//     r = clamp(roughness, MIN_ROUGHNESS, 1),  k = (r + 1)^2 / 8
// (k = alpha / 2 is the image-based-lighting remapping, not this one).
float G_SchlickGGX(float NoV, float NoL, float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    float k = r * r / 2.0;
    return G1_SchlickGGX(NoV, k) * G1_SchlickGGX(NoL, k);
}
