// exercises.glsl: the ten exercise files, taken from the implementation the
// host was asked for (--impl DIR: exercises/ by default for students,
// solutions/ for renders). "exercise/NAME" is resolved by the host.
#include "exercise/01-camera.glsl"
#include "exercise/02-intersect.glsl"
#include "exercise/03-lambert.glsl"
#include "exercise/04-shadows.glsl"
#include "exercise/05-ggx.glsl"
#include "exercise/06-geometry.glsl"
#include "exercise/07-fresnel.glsl"
#include "exercise/08-cook-torrance.glsl"
#include "exercise/09-reflections.glsl"
#include "exercise/10-display.glsl"
