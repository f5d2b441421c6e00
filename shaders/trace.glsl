// trace.glsl: the radiance along a camera ray, by exercise 09's traceRay():
// the first hit and its Fresnel-weighted mirror bounces. traceRay() gets the
// light of each hit and of each ray that leaves the scene from shadeHit()
// and backgroundRadiance() below (lighting.glsl computes it).

// The teaching view "bounce k" keeps only the k-th surface hit (0 = primary)
// or the background seen after k bounces: shadeHit() and backgroundRadiance()
// count the calls a camera ray makes and return 0 for the others.
int g_onlyBounce = -1;  // -1: keep every bounce
int g_bounceCounter = 0;

bool keepThisBounce() {
    bool keep = g_onlyBounce < 0 || g_bounceCounter == g_onlyBounce;
    ++g_bounceCounter;
    return keep;
}

// The light of a hit, for exercise 09 (declarations.glsl). The pixel
// debugger's program records what the exercises compute there first
// (pixel_debug.glsl, debugShadeHit).
vec3 shadeHit(Hit hit, vec3 v) {
    if (!keepThisBounce()) return vec3(0.0);
#ifdef RL_PIXEL_DEBUG
    return debugShadeHit(hit, v, g_bounceCounter - 1);
#else
    return hitRadiance(hit, v);
#endif
}

// The light of a ray that leaves the scene, for exercise 09.
vec3 backgroundRadiance() {
    bool cameraRay = g_bounceCounter == 0;
    bool kept = keepThisBounce();
#ifdef RL_PIXEL_DEBUG
    return debugBackgroundRadiance(cameraRay, kept, g_bounceCounter - 1);
#else
    return kept ? missRadiance(cameraRay) : vec3(0.0);
#endif
}

vec3 radianceAlong(vec3 origin, vec3 dir) {
    g_bounceCounter = 0;
    return traceRay(origin, dir);
}

// ---- Stopping the bounces early (specialised shaders) ------------------------------------
//
// What the rest of a path adds to this sample's linear radiance L is at most
// R |throughput| (per channel), R bounding what one ray can bring back: the
// brightest hit (each light at its shortest distance to a sphere, the BRDF's
// peak, ambient) plus what it reflects over the bounces left, or the
// background (app/render/bounce_cutoff.cpp). The display step g (exposure e,
// tone map, gamma) is increasing and concave, so adding at most d to an
// exposed pixel value of at least a moves the display value by at most
// g'(a) d. This sample is 1/N of its pixel (N samples per pixel) and the
// pixel holds at least its share, so the move is at most
//     g'(e min(L) / N) * e R max(throughput) / N,
// and the bounces stop when that is at most BOUNCE_CUTOFF_TOLERANCE / N: all
// N samples together then move the display value by at most the tolerance.
// docs/performance.md derives it; tests/bench/test_specialisation.cpp tests it.

// A quarter of an 8-bit step: the 8-bit output can change only where the
// exact value lies within 1/1024 of a rounding boundary, and then by one step.
const float BOUNCE_CUTOFF_TOLERANCE = 1.0 / 1024.0;

// Set by the host from the scene (app/render/bounce_cutoff.h, docs/uniforms.md):
//   x: 1 / (e R); 0 when R is unbounded or gamma < 1 (g not concave): then
//      only a zero throughput stops the bounces
//   y: e / N, exposure over samples per pixel
//   z: 1 / gamma, 0 for the sRGB transfer function
//   w: the tone map (a TONEMAP_ constant)
uniform vec4 u_bounceCutoff;

// dg/dc, the slope of the display step at exposed radiance c >= 0: the tone
// map's slope times the gamma encoding's slope at the tone-mapped T. The
// gamma slope grows without bound as T -> 0: T is kept above 1e-30, which
// gives a slope too steep to stop at.
float displaySlope(float c) {
    int op = int(u_bounceCutoff.w);
    float fade = exp(-c);
    float T = op == TONEMAP_REINHARD ? c / (1.0 + c) : op == TONEMAP_EXPONENTIAL ? 1.0 - fade : min(c, 1.0);
    float dT = op == TONEMAP_REINHARD ? 1.0 / ((1.0 + c) * (1.0 + c))
             : op == TONEMAP_EXPONENTIAL ? fade : (c < 1.0 ? 1.0 : 0.0);
    float invGamma = u_bounceCutoff.z;
    bool srgb = invGamma <= 0.0;  // 12.92 T up to 0.0031308, then 1.055 T^(1/2.4) - 0.055
    float exponent = srgb ? 1.0 / 2.4 : invGamma;
    float scale = srgb ? 1.055 / 2.4 : invGamma;
    float dG = srgb && T <= 0.0031308 ? 12.92 : scale * pow(max(T, 1e-30), exponent - 1.0);
    return dG * dT;
}

// True when tracing on from here cannot move this pixel's display value by
// more than BOUNCE_CUTOFF_TOLERANCE. radiance: linear, gathered so far along
// the camera ray; throughput: what the next ray's radiance will be weighted by.
bool bounceCannotChangeOutput(vec3 radiance, vec3 throughput) {
#if defined(RL_BOUNCE_CUTOFF) && !defined(RL_UNIT_LIGHT) && !defined(RL_ENVIRONMENT)  // a unit's light term and the environment are not in the bound R
    float a = u_bounceCutoff.y * min(radiance.r, min(radiance.g, radiance.b));
    float t = max(throughput.r, max(throughput.g, throughput.b));
    return displaySlope(a) * t <= BOUNCE_CUTOFF_TOLERANCE * u_bounceCutoff.x;
#else
    return false;  // generic shaders trace every bounce
#endif
}
