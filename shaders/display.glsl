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

// Notes every exercise whose pure functions still return NOT_STARTED, so the
// stripe frame of stubOverlay() runs round the whole picture, not only round
// the pixels that happened to call a stub. The arguments are constants: the
// compiler folds these calls away. (lightVisibility and traceRay need the
// scene; they are noted where they are called.)
void markUnfinishedExercises() {
    vec3 z = vec3(0.0, 0.0, 1.0);
    Material m = Material(vec3(0.5), 0.5, 0.0, 1.0);
    isStub(sampleOffset(0, 1));
    isStub(cameraRayDirection(vec2(0.5), vec2(1.0), 1.0, vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), -z));
    isStub(intersectSphere(vec3(0.0), -z, vec3(0.0, 0.0, -3.0), 1.0));
    isStub(Fd_Lambert(vec3(0.5)));
    isStub(pointLightIrradiance(vec3(0.0), z, z, vec3(1.0)));
    isStub(offsetRayOrigin(vec3(1.0), z, vec3(1.0)));
    isStub(D_GGX(z, z, 0.25));
    isStub(G1_SchlickGGX(0.5, 0.5));
    isStub(G_SchlickGGX(0.5, 0.5, 0.5));
    isStub(F_Schlick(vec3(0.04), 1.0));
    isStub(ggxAlpha(0.5));
    isStub(baseReflectance(m));
    isStub(cookTorranceBRDF(z, z, z, m));
    isStub(F_SchlickRoughness(vec3(0.04), 1.0, 0.5));
    isStub(toneMap(vec3(0.5), TONEMAP_REINHARD));
    isStub(encodeGamma(vec3(0.5), 2.2));
    isStub(displayEncode(vec3(0.5), 1.0, TONEMAP_REINHARD, 2.2));
}
