// pixel_debug.frag: the pixel debugger (pixel_debug.glsl,
// app/render/pixel_debugger.h). Fragment k of a 1xN target traces the asked
// pixel's centre ray with the implementation's own functions and writes the
// k-th value recorded on the way: (value, key); key 0 past the last.
#include "raytracer.glsl"

uniform vec2 u_debugPixel;  // the asked pixel's lower-left corner: column i, row j from the bottom

layout(location = 0) out vec4 o_value;

void main() {
    g_debugSlot = int(gl_FragCoord.x);
    int n = max(1, int(sqrt(float(u_spp)) + 0.5));
    debugRecord(DBG_SAMPLE_OFFSET, 0, -1, vec3(sampleOffset(0, n), float(n)));
    vec3 right = u_cameraToWorld[0].xyz;
    vec3 up = u_cameraToWorld[1].xyz;
    vec3 forward = -u_cameraToWorld[2].xyz;
    vec3 dir = cameraRayDirection(u_debugPixel + 0.5, u_resolution, cameraFovY(), right, up, forward);
    debugRecord(DBG_CAMERA_RAY, 0, -1, dir);
    g_debugRecording = true;
    vec3 radiance = radianceAlong(cameraPosition(), dir);
    g_debugRecording = false;
    // Each bounce's weight, as the implementation's traceRay() applies it:
    // the same trace with shadeHit() (or the background) 1 at bounce k and 0
    // elsewhere returns the throughput it multiplies bounce k's light by.
    for (int k = 0; k <= maxBounces(); ++k) {
        vec3 weight = vec3(0.0);
        if (g_debugCount == g_debugSlot) {  // only the fragment that writes it traces again
            g_onlyBounce = k;
            g_debugUnitWeight = true;
            weight = radianceAlong(cameraPosition(), dir);
            g_debugUnitWeight = false;
            g_onlyBounce = -1;
        }
        debugRecord(DBG_WEIGHT, k, -1, weight);
    }
    debugRecord(DBG_RADIANCE, 0, -1, radiance);
    debugRecord(DBG_DISPLAY, 0, -1, displayColour(radiance));
    o_value = g_debugValue;
    if (rl_loopTripped != 0) o_value = vec4(0.0, 0.0, 0.0, -1.0);  // a loop of an exercise file ran away
}
