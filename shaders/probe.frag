// probe.frag: the probe program of `raylab check` (see probe.glsl): one
// exercise function evaluated on a grid of inputs, one case per pixel.
#include "raytracer.glsl"
#include "probe.glsl"

layout(location = 0) out vec4 o_result;

void main() {
    o_result = evaluateProbe();
    o_result.w = loopGuardAlpha(o_result.w);  // -ID when a loop of the exercise went over its bound
}
