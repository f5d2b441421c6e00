// declarations.glsl: the contract between the framework and the exercises.
// Every function an exercise implements and every framework function an
// exercise may call, declared here so that the files can be included in any
// order. The exercises' own come from their units (course/*/unit.json,
// "signature"), written by the host; each unit's handout explains them.
#include "exercise_declarations.glsl"

// Framework functions the exercises may call:
Hit closestHit(vec3 origin, vec3 dir, int leaving);                 // intersect_scene.glsl; leaving: the sphere origin lies on, or NO_SPHERE
bool anyHitBefore(vec3 origin, vec3 dir, float tMax, int leaving);  // intersect_scene.glsl
vec3 shadeHit(Hit hit, vec3 v);                        // lighting.glsl: direct light + ambient
vec3 backgroundRadiance();                             // lighting.glsl: what a missed ray sees
Material sphereMaterial(int i);                        // scene.glsl
int maxBounces();                                      // scene.glsl
bool bounceCannotChangeOutput(vec3 radiance, vec3 throughput);  // trace.glsl: nothing more can show
