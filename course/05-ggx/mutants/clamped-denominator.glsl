// mutant of: 05-ggx
// mistake: the denominator clamped, max(denom^2, 1e-7), against a division by zero that cannot happen: it caps D at the peak of a smooth surface (issue 35: it was told to use |n x h|^2, which it does)
// caught by: the check's message or hint contains "the denominator is clamped (max(denom * denom, 1e-07))"
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
    return a2 / (PI * max(denom * denom, 1e-7));
}
