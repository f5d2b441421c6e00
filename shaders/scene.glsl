// scene.glsl: the scene as the host uploads it (docs/uniforms.md).
// Sphere and light arrays live in one std140 uniform block; the host may
// compile counts and the bounce limit in as constants (RL_SPHERE_COUNT,
// RL_LIGHT_COUNT, RL_MAX_BOUNCES) when it specialises the shader to a scene.

#ifndef RL_MAX_SPHERES
#define RL_MAX_SPHERES 64
#endif
#ifndef RL_MAX_LIGHTS
#define RL_MAX_LIGHTS 16
#endif

// Coordinates relative to the scene's anchor (docs/numerics.md, "The anchor
// frame"): a point the host chooses among the spheres and subtracts in double
// before float32, so that a hit point carries float32's rounding of the
// scene's size, not of the camera's distance or of the scene's position in
// the world. Every position (ray origins, Hit.p, the lights) is in it.
layout(std140) uniform SceneBlock {
    vec4 u_sphereGeometry[RL_MAX_SPHERES];  // xyz centre relative to the anchor, w radius (scene units, docs/uniforms.md)
    vec4 u_sphereSurface[RL_MAX_SPHERES];   // rgb albedo (linear), a perceptual roughness
    vec4 u_sphereExtra[RL_MAX_SPHERES];     // x metallic, y ao, z |centre|^2 - r^2 (from double), w 1: refine its roots
    vec4 u_sphereEdgeTint[RL_MAX_SPHERES];  // rgb conductor edge tint (model variants only)
    vec4 u_lightPosition[RL_MAX_LIGHTS];    // xyz position relative to the anchor (scene units)
    vec4 u_lightIntensity[RL_MAX_LIGHTS];   // rgb colour * intensity (linear)
    vec4 u_cameraFromAnchor;                // xyz the camera's position relative to the anchor
    vec4 u_sphereFromCamera[RL_MAX_SPHERES]; // x |camera - centre|^2 - r^2 (from double, per frame), y 1: camera rays take their root from it
    vec4 u_lightSurface[RL_MAX_LIGHTS];      // x the sphere whose surface the light lies within float32's reach of (-1: none), y its side from double: -1 inside, 0 on, 1 outside
};

uniform int u_sphereCount;   // number of valid entries in the sphere arrays
uniform int u_lightCount;    // number of valid entries in the light arrays
uniform int u_maxBounces;    // mirror bounces after the primary hit
uniform float u_ambient;     // ambient radiance factor
uniform vec3 u_background;   // radiance of a ray that hits nothing (linear)

int sphereCount() {
#ifdef RL_SPHERE_COUNT
    return RL_SPHERE_COUNT;
#else
    return u_sphereCount;
#endif
}

int lightCount() {
#ifdef RL_LIGHT_COUNT
    return RL_LIGHT_COUNT;
#else
    return u_lightCount;
#endif
}

int maxBounces() {
#ifdef RL_MAX_BOUNCES
    return RL_MAX_BOUNCES;
#else
    return u_maxBounces;
#endif
}

// ---- The scene's numbers, read through one accessor each ----------------------------------
//
// A program for one scene gets them compiled in (the RL_ macros below, rows
// of app/render/define_table.cpp: each a chain of selects on the index, data
// only, the same float32 values the host would upload): on llvmpipe a
// constant folds into the code that reads it, where a uniform is a load per
// use that nothing folds (a frame of the lecture scene took 2.5 times as
// long with its spheres read from the uniform block, docs/performance.md).
// The generic program reads the uniform block.

// The sphere's centre relative to the anchor (xyz) and its radius (w), scene units.
vec4 sphereGeometry(int i) {
#ifdef RL_SPHERE_GEOMETRY
    return RL_SPHERE_GEOMETRY(i);
#else
    return u_sphereGeometry[i];
#endif
}

Material sphereMaterial(int i) {
#ifdef RL_SPHERE_MATERIAL
    return RL_SPHERE_MATERIAL(i);
#else
    Material m;
    m.albedo = u_sphereSurface[i].rgb;
    m.roughness = u_sphereSurface[i].a;
    m.metallic = u_sphereExtra[i].x;
    m.ao = u_sphereExtra[i].y;
    return m;
#endif
}

// |centre|^2 - r^2 of sphere i, the centre relative to the anchor: the
// constant term of the quadratic of a ray from the anchor, from double
// (error_bounds.glsl).
float sphereAnchorC(int i) {
#ifdef RL_SPHERE_ANCHOR_C
    return RL_SPHERE_ANCHOR_C(i);
#else
    return u_sphereExtra[i].z;
#endif
}

vec3 lightPosition(int i) {
#ifdef RL_LIGHT_POSITION
    return RL_LIGHT_POSITION(i);
#else
    return u_lightPosition[i].xyz;
#endif
}

vec3 lightIntensity(int i) {
#ifdef RL_LIGHT_INTENSITY
    return RL_LIGHT_INTENSITY(i);
#else
    return u_lightIntensity[i].rgb;
#endif
}

// The camera's position, where every camera ray starts. A program for one
// picture gets it as a constant, so that what the camera rays share folds.
vec3 cameraFromAnchor() {
#ifdef RL_CAMERA_FROM_ANCHOR
    return RL_CAMERA_FROM_ANCHOR;
#else
    return u_cameraFromAnchor.xyz;
#endif
}

// Camera rays: |camera - centre|^2 - r^2 of sphere i from double, for this
// frame's camera (x), and whether the exercise's float32 cannot tell the
// camera's side of it (y: 1), error_bounds.glsl.
vec2 cameraSphere(int i) {
#ifdef RL_CAMERA_SPHERE
    return RL_CAMERA_SPHERE(i);
#else
    return u_sphereFromCamera[i].xy;
#endif
}

// A light on, or closer to a sphere's surface than float32 can tell apart
// (docs/model.md, "A light on a surface"): that sphere's index, or -1 (x);
// and which side of it the host found in double (y: -1 inside, 0 on, 1 outside).
vec2 lightSurface(int k) {
#ifdef RL_LIGHT_SURFACE
    return RL_LIGHT_SURFACE(k);
#else
    return u_lightSurface[k].xy;
#endif
}
int lightSurfaceSphere(int k) { return k >= 0 ? int(lightSurface(k).x) : -1; }
float lightSurfaceSide(int k) { return lightSurface(k).y; }

float ambientFactor() {
#ifdef RL_AMBIENT
    return RL_AMBIENT;
#else
    return u_ambient;
#endif
}

vec3 backgroundColour() {
#ifdef RL_BACKGROUND
    return RL_BACKGROUND;
#else
    return u_background;
#endif
}
