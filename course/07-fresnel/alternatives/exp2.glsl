// alternative of: 07-fresnel
// written as: (1 - VoH)^5 as exp2(5 log2(1 - VoH)), the way pow() is defined (max() keeps log2 away from 0, where GLSL leaves it undefined)
// expected: PASS (a correct solution written differently)
// Exercise 07: Schlick's Fresnel. Handout: course/07-fresnel/handout.md

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//     F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5
vec3 F_Schlick(vec3 F0, float VoH) {
    float m = max(1.0 - clamp(VoH, 0.0, 1.0), 1e-7);  // (1e-7)^5 = 1e-35: as good as 0
    return F0 + (1.0 - F0) * exp2(5.0 * log2(m));
}
