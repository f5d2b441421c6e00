// display.glsl: linear radiance to a display-encoded colour in [0, 1], by
// exercise 10. Until it is written: clamp only (no exposure, tone map or gamma).
uniform float u_exposure;  // multiplies radiance before tone mapping
uniform int u_toneMap;     // TONEMAP_REINHARD, TONEMAP_EXPONENTIAL or TONEMAP_NONE
uniform float u_gamma;     // display gamma; 0 selects the exact sRGB transfer function

vec3 displayColour(vec3 radiance) {
    bool ready = !isStub(toneMap(vec3(0.5), TONEMAP_REINHARD)) && !isStub(encodeGamma(vec3(0.5), 2.2));
    vec3 c = ready ? displayEncode(radiance, u_exposure, u_toneMap, u_gamma) : vec3(NOT_STARTED);
    if (isStub(c)) return clamp(radiance, 0.0, 1.0);
    return clamp(c, 0.0, 1.0);
}
