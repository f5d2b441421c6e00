// Exercise 10: exposure, tone mapping and gamma. Handout: course/10-display/handout.md
//
// Until you write these, the picture is linear radiance clamped to [0, 1].

// Tone mapping of exposed linear radiance c >= 0 into [0, 1]:
//     TONEMAP_REINHARD: c / (1 + c);  TONEMAP_EXPONENTIAL: 1 - exp(-c);  TONEMAP_NONE: clamp(c, 0, 1)
vec3 toneMap(vec3 c, int op) {
    return vec3(NOT_STARTED);  // TODO
}

// Display encoding of c in [0, 1]: c^(1/gamma) when gamma > 0; when gamma is 0,
// the exact sRGB transfer function:  c <= 0.0031308 ? 12.92 c : 1.055 c^(1/2.4) - 0.055
vec3 encodeGamma(vec3 c, float gamma) {
    return vec3(NOT_STARTED);  // TODO
}

// The display step, in this order: exposure (multiply), tone map, gamma.
vec3 displayEncode(vec3 radiance, float exposure, int op, float gamma) {
    return vec3(NOT_STARTED);  // TODO
}
