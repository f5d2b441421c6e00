// display.glsl: linear radiance to a display-encoded colour in [0, 1], by
// exercise 10 (exposure, tone map, gamma), clamped.
uniform float u_exposure;  // multiplies radiance before tone mapping
uniform int u_toneMap;     // TONEMAP_REINHARD, TONEMAP_EXPONENTIAL or TONEMAP_NONE
uniform float u_gamma;     // display gamma; 0 selects the exact sRGB transfer function

// A program for one picture gets them as constants (RL_EXPOSURE, RL_TONE_MAP,
// RL_GAMMA: app/render/define_table.cpp), so that exercise 10's choices fold.
vec3 displayColour(vec3 radiance) {
#ifdef RL_EXPOSURE
    return clamp(displayEncode(radiance, RL_EXPOSURE, RL_TONE_MAP, RL_GAMMA), 0.0, 1.0);
#else
    return clamp(displayEncode(radiance, u_exposure, u_toneMap, u_gamma), 0.0, 1.0);
#endif
}
