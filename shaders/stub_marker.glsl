// stub_marker.glsl: how the framework notices an unfinished exercise.
// isStub(x) is true when an exercise returned NOT_STARTED and remembers that
// the picture used a stub; stubOverlay() then paints a frame of diagonal
// grey/magenta stripes around the picture, so it shows unmistakably that it
// is not the finished model while the neutral picture inside stays readable.
// Where a pixel has no geometry at all because exercise 01 or 02 is a stub
// (isGeometryStub), the whole pixel is striped.

bool g_usedStub = false;
bool g_missingGeometry = false;

#ifdef RL_EXERCISES_FINISHED
// Every exercise file is written and none of them names NOT_STARTED (the host
// checked, ImplementationFacts in app/render/implementation_facts.h): no
// function can return the sentinel, so every test of it folds away. On
// llvmpipe a test of a ray-dependent value costs its full price in every
// pixel, taken or not (docs/performance.md).
bool isStub(float x) { return false; }
#else
bool isStub(float x) {
    if (x == NOT_STARTED) {
        g_usedStub = true;
        return true;
    }
    return false;
}
#endif
bool isStub(vec2 x) { return isStub(x.x); }
bool isStub(vec3 x) { return isStub(x.x); }

bool isGeometryStub(float x) {
    if (!isStub(x)) return false;
    g_missingGeometry = true;
    return true;
}
bool isGeometryStub(vec3 x) { return isGeometryStub(x.x); }

// colour: display-encoded. Stripes 12 pixels wide, half magenta, half grey,
// blended 35%; the frame is 2.5% of the smaller side (at least 6 pixels).
vec3 stubOverlay(vec3 colour, vec2 fragCoord, vec2 resolution) {
    vec2 fromEdge = min(fragCoord, resolution - fragCoord);
    bool inFrame = min(fromEdge.x, fromEdge.y) < max(6.0, 0.025 * min(resolution.x, resolution.y));
    if (!g_missingGeometry && !(g_usedStub && inFrame)) return colour;
    bool band = mod(floor((fragCoord.x + fragCoord.y) / 12.0), 2.0) < 1.0;
    vec3 stripe = band ? vec3(0.85, 0.15, 0.85) : vec3(0.5);
    return mix(colour, stripe, 0.35);
}
