// alternative of: 05-ggx
// written as: Filament's D_GGX (surface_brdf.fs): k = alpha / (1 - NoH^2 + (NoH alpha)^2), D = k^2 / pi, with 1 - NoH^2 as |n x h|^2 as Filament does in half precision
// expected: PASS (a correct solution written differently)
// Exercise 05: the GGX normal distribution. Handout: course/05-ggx/handout.md

// GGX / Trowbridge-Reitz normal distribution function.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces":
//     D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// Written with 1 - (n.h)^2 = |n x h|^2: near the peak (n.h -> 1) the
// subtraction cancels in float32, the cross product does not (Filament).
float D_GGX(vec3 n, vec3 h, float alpha) {
    // Walter et al. 2007, in Filament's form
    float NoH = dot(n, h);
    vec3 NxH = cross(n, h);
    float oneMinusNoHSquared = dot(NxH, NxH);
    float a = NoH * alpha;
    float k = alpha / (oneMinusNoHSquared + a * a);
    return k * k * (1.0 / PI);
}
