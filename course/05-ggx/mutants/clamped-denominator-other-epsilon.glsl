// mutant of: 05-ggx
// mistake: the denominator clamped at an epsilon no recogniser knows (3e-9): the group hint still names the clamp
// caught by: the check's message or hint contains "a clamp of the denominator (max(..., eps)) caps the peak"
// Exercise 05: the GGX normal distribution. Handout: course/05-ggx/handout.md

// GGX / Trowbridge-Reitz normal distribution function.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces":
//     D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// Written with 1 - (n.h)^2 = |n x h|^2: near the peak (n.h -> 1) the
// subtraction cancels in float32, the cross product does not (Filament).
float D_GGX(vec3 n, vec3 h, float alpha) {
    float NoH = dot(n, h);
    vec3 NxH = cross(n, h);
    float a2 = alpha * alpha;
    float denom = dot(NxH, NxH) + NoH * NoH * a2;  // = (n.h)^2 (alpha^2 - 1) + 1
    return a2 / (PI * max(denom * denom, 3e-9));
}
