// main.frag: the ray tracer, one pixel per invocation. Read top to bottom:
// modules in the order they build on each other, then main().
#include "raytracer.glsl"

layout(location = 0) out vec4 o_display;   // display-encoded colour (8-bit PNG after rounding); alpha 0: marked
layout(location = 1) out vec4 o_radiance;  // linear radiance averaged over the samples (PFM)

// A program that checks an assumption pixel by pixel (the sky tiles' miss,
// shadow rays from the light's side: app/render/define_table.cpp) marks the
// pixels where it does not hold: alpha 0 in o_display, and a depth of 0
// against 1, so that the host draws just those pixels again with the
// program that makes no assumption (render/gl_renderer.h), its depth test
// skipping the others 8 pixels at a time.
#if defined(RL_SKY) || defined(RL_SHADOW_STEPS)
#define RL_MARKS_PIXELS
#endif

void main() {
    vec2 pixel = floor(gl_FragCoord.xy);  // (i, j), j counted from the bottom
#ifdef RL_SAMPLE_GRID  // a program for one picture: n compiled in (define_table.cpp), sampleOffset folds
    const int n = RL_SAMPLE_GRID;
#else
    int n = max(1, int(sqrt(float(u_spp)) + 0.5));
#endif
    if (u_view == VIEW_BOUNCE) g_onlyBounce = u_viewBounce;
    bool traced = u_view == VIEW_FINAL || u_view == VIEW_BOUNCE;
    vec3 sum = vec3(0.0);
    // The samples' loop tests its condition at the end: llvmpipe runs a loop's
    // body once more with every pixel masked off after the test at the top
    // fails, and this body is the whole ray tracer (a third of the frame
    // with one sample, docs/performance.md).
    int s = 0;
    do {
        vec3 dir = primaryRayDirection(pixel, s, n);
#ifdef RL_PICTURE_ONLY  // a program for the picture and the bounce views: no term views (define_table.cpp)
        sum += radianceAlong(cameraPosition(), dir);
#else
        sum += traced ? radianceAlong(cameraPosition(), dir) : teachingView(cameraPosition(), dir);
#endif
    } while (++s < n * n);
    vec3 radiance = sum / float(n * n);  // the spec averages radiance before the display step
    vec3 colour = viewIsRadiance() ? displayColour(radiance) : clamp(radiance, 0.0, 1.0);
    if (rl_loopTripped != 0) colour = vec3(1.0, 0.0, 1.0);  // a loop of an exercise file went over its bound
#ifdef RL_MARKS_PIXELS
    o_display = vec4(stubOverlay(colour, gl_FragCoord.xy, resolution()), g_assumptionBroken ? 0.0 : 1.0);
    gl_FragDepth = g_assumptionBroken ? 0.0 : 1.0;
#else
    o_display = vec4(stubOverlay(colour, gl_FragCoord.xy, resolution()), 1.0);
#endif
    o_radiance = vec4(radiance, loopGuardAlpha(1.0));
}
