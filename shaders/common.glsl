// common.glsl: constants and types shared by the framework, the exercises
// and the probe shaders. Colour values are LINEAR radiance unless a name or
// comment says "display-encoded".

const float PI = 3.14159265358979;

// The model's constants (docs/model.md, "Constants"): their one definition in
// the GLSL; the CPU reference's are in app/reference/brdf_reference.h and
// app/core/float_range.h.
//
// The least perceptual roughness shading uses: r = clamp(roughness,
// MIN_ROUGHNESS, 1) keeps alpha^2 = r^4 = 4.1e-6 above 0, so GGX's D stays
// finite at NoH = 1 for a mirror (roughness 0).
const float MIN_ROUGHNESS = 0.045;
// u = 2^-24, the unit roundoff of float32: a correctly rounded operation on x
// is off by at most u |x| (error_bounds.glsl).
const float UNIT_ROUNDOFF = 5.9604644775390625e-8;

// intersectSphere() returns NO_HIT when the ray misses (any t <= 0 is a miss).
const float NO_HIT = -1.0;

// Every exercise stub returns NOT_STARTED (a float, or vec3(NOT_STARTED)).
// No finished exercise can return it: it is negative where every result is a
// distance, a colour or a factor, and far outside any real value. The
// framework recognises it, substitutes a neutral value and paints the pixel
// with grey/magenta stripes; `raylab check` reports NOT STARTED.
const float NOT_STARTED = -1.0e30;

// Hit.sphere of a camera ray's origin, which lies on no sphere.
const int NO_SPHERE = -1;

// Tone-mapping operators (the scene's "tonemap").
const int TONEMAP_REINHARD = 0;
const int TONEMAP_EXPONENTIAL = 1;
const int TONEMAP_NONE = 2;

struct Material {
    vec3 albedo;      // linear base colour
    float roughness;  // perceptual roughness r, as in the scene file (not clamped)
    float metallic;   // 0 dielectric, 1 metal
    float ao;         // ambient occlusion, scales the ambient term only
};

struct Hit {
    float t;          // distance along the (unit) ray direction; NO_HIT for a miss
    vec3 p;           // hit point relative to the scene's anchor (scene.glsl), reprojected onto the sphere
    vec3 n;           // unit normal, flipped to face the incoming ray
    vec3 error;       // componentwise bound on |p - the exact surface point| (error_bounds.glsl)
    int sphere;       // index of the sphere hit (NO_SPHERE for none)
    vec4 sphereGeometry;  // framework: that sphere's centre (xyz) and radius (w)
};

float maxAbs(vec3 v) {
    vec3 a = abs(v);
    return max(a.x, max(a.y, a.z));
}
