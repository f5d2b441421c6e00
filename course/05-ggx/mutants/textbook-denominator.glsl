// mutant of: 05-ggx
// mistake: the textbook denominator (n.h)^2 (alpha^2 - 1) + 1, which cancels near the peak in float32
// caught by: the check's message or hint contains "cancels in float32"
// also breaks the hard case: the GGX peak probe (tests/accuracy/test_brdf_physics.cpp) and scenes/hard/ggx-peak.json
// Exercise 05: the GGX normal distribution. Handout: course/05-ggx/handout.md

// GGX / Trowbridge-Reitz normal distribution function.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces":
//     D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// Written with 1 - (n.h)^2 = |n x h|^2: near the peak (n.h -> 1) the
// subtraction cancels in float32, the cross product does not (Filament).
float D_GGX(vec3 n, vec3 h, float alpha) {
    float NoH = dot(n, h);
    float a2 = alpha * alpha;
    float denom = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * denom * denom);
}
