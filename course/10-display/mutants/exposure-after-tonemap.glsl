// mutant of: 10-display
// mistake: exposure applied after tone mapping
// caught by: the check's message or hint contains "exposure is applied after tone mapping"
// Exercise 10: exposure, tone mapping and gamma. Handout: course/10-display/handout.md

// Tone mapping of exposed linear radiance c >= 0 into [0, 1]:
//     reinhard: c / (1 + c);  exponential: 1 - exp(-c);  none: clamp(c, 0, 1)
vec3 toneMap(vec3 c, int op) {
    if (op == TONEMAP_REINHARD) return c / (1.0 + c);
    if (op == TONEMAP_EXPONENTIAL) return 1.0 - exp(-c);
    return clamp(c, 0.0, 1.0);
}

// Display encoding of a tone-mapped value c in [0, 1]: c^(1/gamma), or the
// exact sRGB transfer function when gamma is 0 (the scene's "srgb"):
//     c <= 0.0031308 ? 12.92 c : 1.055 c^(1/2.4) - 0.055
vec3 encodeGamma(vec3 c, float gamma) {
    if (gamma > 0.0) return pow(c, vec3(1.0 / gamma));
    vec3 low = 12.92 * c;
    vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(c, vec3(0.0031308)));
}

// The display step, in this order: exposure, tone map, gamma.
vec3 displayEncode(vec3 radiance, float exposure, int op, float gamma) {
    return encodeGamma(toneMap(radiance, op) * exposure, gamma);  // MUTANT: exposure last
}
