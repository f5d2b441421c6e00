// portability slip in: 07-fresnel
// slip: return F0 + (1.0 - F0) * pow(m, 5);  (Mesa's desktop GLSL accepts it, GLSL ES 3.00 does not)
// reported as: "pow(float, int) does not exist in GLSL ES: write `pow(m, 5.0)`"
// Exercise 07: Schlick's Fresnel. Handout: course/07-fresnel/handout.md

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//     F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5
vec3 F_Schlick(vec3 F0, float VoH) {
    float m = 1.0 - clamp(VoH, 0.0, 1.0);
    return F0 + (1.0 - F0) * pow(m, 5);
}
