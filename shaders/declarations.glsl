// declarations.glsl: the contract between the framework and the exercises.
// Every function an exercise implements (left) and every framework function
// an exercise may call (right), declared here so that the files can be
// included in any order. The handouts in docs/exercises/ explain each one.

// 01-camera
vec2 sampleOffset(int s, int n);
vec3 cameraRayDirection(vec2 pixelSample, vec2 resolution, float fovY, vec3 right, vec3 up, vec3 forward);
// 02-intersect
float intersectSphere(vec3 origin, vec3 dir, vec3 center, float radius);
// 03-lambert
vec3 Fd_Lambert(vec3 albedo);
vec3 pointLightIrradiance(vec3 p, vec3 n, vec3 lightPosition, vec3 lightIntensity);
// 04-shadows
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 pError);
float lightVisibility(Hit hit, vec3 lightPosition);
// 05-ggx
float D_GGX(vec3 n, vec3 h, float alpha);
// 06-geometry
float G1_SchlickGGX(float NoX, float k);
float G_SchlickGGX(float NoV, float NoL, float roughness);
// 07-fresnel
vec3 F_Schlick(vec3 F0, float VoH);
// 08-cook-torrance
float ggxAlpha(float roughness);
vec3 baseReflectance(Material m);
vec3 specularBRDF(vec3 n, vec3 v, vec3 l, Material m);
vec3 diffuseBRDF(vec3 n, vec3 v, vec3 l, Material m);
vec3 cookTorranceBRDF(vec3 n, vec3 v, vec3 l, Material m);
// 09-reflections
vec3 F_SchlickRoughness(vec3 F0, float NoV, float roughness);
vec3 traceRay(vec3 origin, vec3 dir);
// 10-display
vec3 toneMap(vec3 c, int op);
vec3 encodeGamma(vec3 c, float gamma);
vec3 displayEncode(vec3 radiance, float exposure, int op, float gamma);

// Framework functions the exercises may call:
Hit closestHit(vec3 origin, vec3 dir, int leaving);                 // intersect_scene.glsl; leaving: the sphere origin lies on, or NO_SPHERE
bool anyHitBefore(vec3 origin, vec3 dir, float tMax, int leaving);  // intersect_scene.glsl
vec3 shadeHit(Hit hit, vec3 v);                        // lighting.glsl: direct light + ambient
vec3 backgroundRadiance();                             // lighting.glsl: what a missed ray sees
Material sphereMaterial(int i);                        // scene.glsl
int maxBounces();                                      // scene.glsl
bool bounceCannotChangeOutput(vec3 radiance, vec3 throughput);  // trace.glsl: nothing more can show
