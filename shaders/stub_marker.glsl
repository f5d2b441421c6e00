// stub_marker.glsl: how the framework notices an unfinished exercise.
// isStub(x) is true when an exercise returned NOT_STARTED; it also remembers
// that this pixel used a stub, and stubOverlay() then paints the pixel with
// diagonal grey/magenta stripes so the picture shows it unmistakably.

bool g_usedStub = false;

bool isStub(float x) {
    if (x == NOT_STARTED) {
        g_usedStub = true;
        return true;
    }
    return false;
}
bool isStub(vec2 x) { return isStub(x.x); }
bool isStub(vec3 x) { return isStub(x.x); }

// colour: display-encoded. Stripes 12 pixels wide, half magenta, half grey,
// blended 50% so the neutral picture underneath stays visible.
vec3 stubOverlay(vec3 colour, vec2 fragCoord) {
    if (!g_usedStub) return colour;
    bool band = mod(floor((fragCoord.x + fragCoord.y) / 12.0), 2.0) < 1.0;
    vec3 stripe = band ? vec3(0.85, 0.15, 0.85) : vec3(0.5);
    return mix(colour, stripe, 0.5);
}
