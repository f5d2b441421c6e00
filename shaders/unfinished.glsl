// unfinished.glsl: the stripes that mark a picture made with unfinished
// exercises. The host decides what is ready and compiles the facts into the
// generated exercises.glsl (app/shader/readiness.h): RL_UNFINISHED when any
// exercise function is not ready (it runs there on the framework's neutral
// value), RL_READY_<function> for each one that is.
//
// stubOverlay() paints a frame of diagonal grey/magenta stripes round the
// picture, so it shows unmistakably that it is not the finished model while
// the neutral picture inside stays readable. Without a camera ray (01) or an
// intersection (02) there is no geometry at all: then every pixel is striped.

// True when the picture has no geometry to show: every pixel striped.
bool missingGeometry() {
#ifndef RL_READY_cameraRayDirection
    return true;
#elif !defined(RL_READY_intersectSphere)
    return sphereCount() > 0;  // no sphere, nothing missing
#else
    return false;
#endif
}

// colour: display-encoded. Stripes 12 pixels wide, half magenta, half grey,
// blended 35%; the frame is 2.5% of the smaller side (at least 6 pixels).
vec3 stubOverlay(vec3 colour, vec2 fragCoord, vec2 resolution) {
#ifndef RL_UNFINISHED
    return colour;
#else
    vec2 fromEdge = min(fragCoord, resolution - fragCoord);
    bool inFrame = min(fromEdge.x, fromEdge.y) < max(6.0, 0.025 * min(resolution.x, resolution.y));
    if (!missingGeometry() && !inFrame) return colour;
    bool band = mod(floor((fragCoord.x + fragCoord.y) / 12.0), 2.0) < 1.0;
    vec3 stripe = band ? vec3(0.85, 0.15, 0.85) : vec3(0.5);
    return mix(colour, stripe, 0.35);
#endif
}
