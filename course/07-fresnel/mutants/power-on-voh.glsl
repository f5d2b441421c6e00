// mutant of: 07-fresnel
// mistake: (1 - (h.v)^5) instead of (1 - h.v)^5
// caught by: the check's message or hint contains "(1 - VoH^5)"
// Exercise 07: Schlick's Fresnel. Handout: course/07-fresnel/handout.md

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering":
//     F = F0 + (1 - F0) (1 - clamp(VoH, 0, 1))^5
vec3 F_Schlick(vec3 F0, float VoH) {
    float x = clamp(VoH, 0.0, 1.0);
    return F0 + (1.0 - F0) * (1.0 - pow(x, 5.0));
}
