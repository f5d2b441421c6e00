// Exercise 07: Schlick's Fresnel. Handout: course/07-fresnel/handout.md

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//     F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5
vec3 F_Schlick(vec3 F0, float VoH) {
    float m = 1.0 - clamp(VoH, 0.0, 1.0);
    float m2 = m * m;
    return F0 + (1.0 - F0) * (m2 * m2 * m);
}
