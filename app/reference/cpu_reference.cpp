// cpu_reference.cpp: the CPU renderer of the reference model. Read top to
// bottom: visibility, shading, bounces, the picture, then the energy integral.
#include "reference/cpu_reference.h"

#include "reference/unit_light.h"

#include "core/error.h"
#include "core/light_surface.h"
#include "reference/environment_reference.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace rl::ref {

bool referenceInThisCopy() { return true; }  // a student edition compiles absent.cpp instead


using glm::dvec2;
using glm::dvec3;

namespace {

double maxAbs(dvec3 v) {
    dvec3 a = glm::abs(v);
    return std::max(a.x, std::max(a.y, a.z));
}

// Unit roundoff of double, 2^-53.
constexpr double kUnitRoundoff = 1.0 / 9007199254740992.0;

// Hit::error relative to maxAbs(centre) + radius: 2^-48 = 32 unit roundoffs.
// The reprojected p = centre + radius u (u = normalize(p0 - centre)) is off
// the true surface by at most |u| - 1 (about 3 roundoffs of normalize)
// times the radius plus the rounding of the sum (1 roundoff of
// maxAbs(centre) + radius per component, sqrt(3) in length): under 6
// roundoffs of maxAbs(centre) + radius (pbrt-v4 section 6.8.5 bounds the
// same reprojection by gamma(5) |p|). 32 leaves a factor 5 for deciding
// another sphere's inside from that origin, and is still 4e-15 of the
// scene's size: no contact shadow or silhouette moves by a pixel.
constexpr double kHitErrorRelative = 32.0 * kUnitRoundoff;

// The two roots t0 <= t1 of |origin + t dir - centre| = radius for a unit
// dir, in the numerically stable form (Haines et al. 2019, Ray Tracing Gems
// ch. 7): f = origin - centre, b = f.dir, disc = r^2 - |f - b dir|^2,
// c = |f|^2 - r^2, q = -b - sign(b) sqrt(disc), roots c/q and q.
// False when the line misses the sphere.
bool sphereRoots(dvec3 origin, dvec3 dir, dvec3 centre, double radius, double& t0, double& t1) {
    dvec3 f = origin - centre;
    double b = glm::dot(f, dir);
    dvec3 perpendicular = f - b * dir;  // centre to the line's closest point
    double discriminant = radius * radius - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0.0) return false;
    double c = glm::dot(f, f) - radius * radius;
    double q = -b - (b >= 0.0 ? 1.0 : -1.0) * std::sqrt(discriminant);  // sign(0) = +1 keeps both roots
    if (q == 0.0) {  // origin on the surface, line tangent: one double root at 0
        t0 = t1 = 0.0;
        return true;
    }
    t0 = c / q;
    t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

// Sphere i has the surface of sphere `left`, the one a ray leaves: it is that
// sphere or an identical one (same centre and radius; the first of them wins
// a camera ray's hit). Both are handled exactly. `twins`: whether `left` has
// an identical sphere at all (Hit::hasTwin, found where the two tie for the
// nearest hit), which spares the comparison in the inner loops.
bool identicalSpheres(const Scene& scene, int i, int j) {
    const Sphere& a = scene.spheres[size_t(i)];
    const Sphere& b = scene.spheres[size_t(j)];
    return a.radius == b.radius && a.center == b.center;
}
inline bool sameSurface(const Scene& scene, int i, int left, bool twins) {
    return i == left || (twins && left >= 0 && identicalSpheres(scene, i, left));
}

// The hit at distance t along the ray on sphere `index`, met from inside or
// not: p reprojected onto the sphere (pbrt-v4 section 6.8.5), so that its
// error is bounded by the sphere's size whatever the ray origin and t (a
// camera 3000 away would otherwise put 3000 x 1e-16 into p), and the normal
// of unit length by construction.
Hit makeHit(const Scene& scene, int index, double t, bool inside, bool hasTwin, dvec3 origin, dvec3 dir) {
    const Sphere& s = scene.spheres[size_t(index)];
    Hit hit;
    hit.t = t;
    hit.sphere = index;
    hit.inside = inside;
    dvec3 radial = origin + t * dir - s.center;
    double length = glm::length(radial);
    // radial = 0 only for a sphere whose radius underflows next to its centre:
    // the normal that faces the ray is then -dir.
    dvec3 u = length > 0.0 ? radial / length : (inside ? dir : -dir);
    hit.p = s.center + s.radius * u;
    hit.n = inside ? -u : u;
    hit.magnitude = std::max(maxAbs(hit.p), maxAbs(s.center) + s.radius);
    hit.error = kHitErrorRelative * (maxAbs(s.center) + s.radius);
    hit.hasTwin = hasTwin;
    return hit;
}

// The nearest t > 0 of sphere i along the ray, and from which side, or false.
bool nearestRoot(const Sphere& s, dvec3 origin, dvec3 dir, double& t, bool& inside) {
    double t0, t1;
    if (!sphereRoots(origin, dir, s.center, s.radius, t0, t1)) return false;
    if (t0 > 0.0) {  // the near root is ahead: the ray comes from outside
        t = t0;
        inside = false;
        return true;
    }
    if (t1 > 0.0) {  // the near root is behind: the origin is inside, the far root ahead
        t = t1;
        inside = true;
        return true;
    }
    return false;
}

// Exit distance of the ray that leaves sphere s's surface at p into it
// (unit dir, dir.(p - centre) <= 0): the roots are 0 and -2 (p - centre).dir.
// Never below 0: a ray inside a closed sphere cannot miss it (a rounded
// tangent direction meets it again at p itself).
double exitDistance(const Sphere& s, dvec3 p, dvec3 dir) {
    return std::max(-2.0 * glm::dot(p - s.center, dir), 0.0);
}

// The nearest root seen so far along one ray, and whether an identical
// sphere ties with it (the same inputs give the same t).
struct NearestRoot {
    int sphere = -1;
    double t = std::numeric_limits<double>::infinity();
    bool inside = false;
    bool twin = false;

    void consider(const Scene& scene, int i, double ti, bool insideI) {
        if (ti < t) {
            t = ti;
            sphere = i;
            inside = insideI;
            twin = false;
        } else if (ti == t) {
            twin = twin || identicalSpheres(scene, i, sphere);
        }
    }
};

}  // namespace

// ---- visibility ------------------------------------------------------------------

bool closestHit(const Scene& scene, dvec3 origin, dvec3 dir, Hit& out) {
    NearestRoot nearest;
    for (int i = 0; i < int(scene.spheres.size()); ++i) {
        double t;
        bool inside;
        if (nearestRoot(scene.spheres[size_t(i)], origin, dir, t, inside)) nearest.consider(scene, i, t, inside);
    }
    if (nearest.sphere < 0) return false;
    out = makeHit(scene, nearest.sphere, nearest.t, nearest.inside, nearest.twin, origin, dir);
    return true;
}

bool nextHit(const Scene& scene, const Hit& from, dvec3 dir, Hit& out) {
    NearestRoot nearest;
    dvec3 origin = from.p + from.n * from.error;  // for the other spheres: p pushed past its rounding error
    for (int i = 0; i < int(scene.spheres.size()); ++i) {
        double t;
        bool inside;
        if (sameSurface(scene, i, from.sphere, from.hasTwin)) {
            // The sphere the ray leaves: from outside it is behind the ray for
            // good; from inside the ray meets it again at its exit distance.
            if (!from.inside) continue;
            t = exitDistance(scene.spheres[size_t(i)], from.p, dir);
            inside = true;
        } else if (!nearestRoot(scene.spheres[size_t(i)], origin, dir, t, inside)) {
            continue;
        }
        nearest.consider(scene, i, t, inside);
    }
    if (nearest.sphere < 0) return false;
    dvec3 start = sameSurface(scene, nearest.sphere, from.sphere, from.hasTwin) ? from.p : origin;
    out = makeHit(scene, nearest.sphere, nearest.t, nearest.inside, nearest.twin, start, dir);
    return true;
}

bool anyHitBefore(const Scene& scene, dvec3 origin, dvec3 dir, double tMax) {
    for (const Sphere& s : scene.spheres) {
        double t = intersectSphere(origin, dir, s.center, s.radius);
        if (t > 0.0 && t < tMax) return true;
    }
    return false;
}

bool lightVisible(const Scene& scene, const Hit& hit, dvec3 lightPosition) {
    dvec3 origin = offsetRayOrigin(hit.p, hit.n, hit.magnitude);
    dvec3 toLight = lightPosition - origin;
    double distance = glm::length(toLight);
    if (distance == 0.0) return true;  // the light sits on the ray origin: nothing can be in between
    return !anyHitBefore(scene, origin, toLight / distance, distance);
}

bool lightReachable(const Scene& scene, const Hit& hit, dvec3 lightPosition) {
    // The sphere of the hit (and any identical one): only from inside, where
    // the ray crosses it at its exit distance (beyond the light when the light
    // is inside it too).
    // A light on a sphere's surface is hidden by neither side of that surface
    // (docs/model.md, "A light on a surface"): its side, not a root at the
    // light's distance that rounds either way, decides.
    const Sphere& own = scene.spheres[size_t(hit.sphere)];
    if (hit.inside && lightSurfaceSide(lightPosition, own) != 0) {
        dvec3 toLight = lightPosition - hit.p;
        double distance = glm::length(toLight);
        if (distance == 0.0) return true;  // the light on p: nothing in between
        if (exitDistance(scene.spheres[size_t(hit.sphere)], hit.p, toLight / distance) < distance) return false;
    }
    dvec3 origin = hit.p + hit.n * hit.error;
    dvec3 toLight = lightPosition - origin;
    double distance = glm::length(toLight);
    if (distance == 0.0) return true;
    dvec3 dir = toLight / distance;
    for (int i = 0; i < int(scene.spheres.size()); ++i) {
        if (sameSurface(scene, i, hit.sphere, hit.hasTwin)) continue;
        const Sphere& s = scene.spheres[size_t(i)];
        double t0, t1;
        if (!sphereRoots(origin, dir, s.center, s.radius, t0, t1)) continue;
        if (lightSurfaceSide(lightPosition, s) == 0) {
            // On its surface: hidden only by a segment that enters the sphere
            // before the light, and so arrives at it moving outward.
            if (t0 > 0.0 && glm::dot(dir, lightPosition - s.center) > 0.0) return false;
            continue;
        }
        // Occluded when the ray enters or leaves the sphere before the light.
        if ((t0 > 0.0 && t0 < distance) || (t1 > 0.0 && t1 < distance)) return false;
    }
    return true;
}

// ---- shading ---------------------------------------------------------------------

dvec3 directLight(const Scene& scene, const Hit& hit, dvec3 v) {
    const Material& m = scene.spheres[hit.sphere].material;
    dvec3 radiance(0.0);
    for (const Light& light : scene.lights) {
        dvec3 E = pointLightIrradiance(hit.p, hit.n, light.position, light.color * light.intensity);
        if (E == dvec3(0.0)) continue;  // facing away, or light at p: no shadow ray needed
        if (!lightReachable(scene, hit, light.position)) continue;
        dvec3 l = glm::normalize(light.position - hit.p);
        radiance += cookTorranceBRDF(hit.n, v, l, m, scene.model) * E;
    }
    return radiance;
}

dvec3 shadeHit(const Scene& scene, const Hit& hit, dvec3 v) {
    const Material& m = scene.spheres[hit.sphere].material;
    dvec3 radiance = directLight(scene, hit, v) + scene.render.ambient * m.albedo * m.ao;
    // The course's units' further light terms (reference/unit_light.h).
    for (const UnitLightTerm& term : unitLightTerms()) radiance += term.radiance({hit.p, hit.n, v, m, &scene});
    return radiance;
}

namespace {

// The seed of a camera ray's environment estimates: the options' seed and
// the ray's bits, so that every pixel sample draws its own numbers whatever
// thread renders it.
std::uint64_t raySeed(std::uint64_t seed, dvec3 origin, dvec3 dir) {
    std::uint64_t h = seed;
    for (double x : {origin.x, origin.y, origin.z, dir.x, dir.y, dir.z}) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = mixSeed(h, bits);
    }
    return h;
}

}  // namespace

dvec3 traceRadiance(const Scene& scene, dvec3 origin, dvec3 dir) {
    return traceRadiance(scene, origin, dir, EnvironmentOptions{});
}

dvec3 traceRadiance(const Scene& scene, dvec3 origin, dvec3 dir, const EnvironmentOptions& options) {
    dvec3 radiance(0.0);
    dvec3 throughput(1.0);
    const bool environment = scene.environment.has_value();
    const std::uint64_t seed = environment ? raySeed(options.seed, origin, dir) : 0;
    Hit hit;
    bool found = closestHit(scene, origin, dir, hit);
    for (int bounce = 0;; ++bounce) {
        if (!found) {
            if (!environment)
                radiance += throughput * scene.render.background;
            else if (bounce == 0)  // a camera ray that hits nothing sees the environment
                radiance += environmentRadiance(*scene.environment, dir);
            // A mirror bounce that escapes adds nothing more: the environment
            // in its direction is part of the environment light of the hit it
            // left (docs/model.md, "Environment light").
            break;
        }
        radiance += throughput * shadeHit(scene, hit, -dir);
        if (environment)
            radiance += throughput * environmentLight(scene, hit, -dir, options, mixSeed(seed, std::uint64_t(bounce)));
        if (bounce == scene.render.maxBounces) break;
        const Material& m = scene.spheres[size_t(hit.sphere)].material;
        double NoV = std::clamp(glm::dot(hit.n, -dir), kMinNoV, 1.0);  // the spec's NdotV clamp
        throughput *= F_SchlickRoughness(baseReflectance(m), NoV, m.roughness);
        // reflect() keeps |d| = 1 only to a few roundoffs; renormalised, the
        // error does not build up over the bounces.
        dir = glm::normalize(glm::reflect(dir, hit.n));
        Hit next;
        found = nextHit(scene, hit, dir, next);
        hit = next;
    }
    return radiance;
}

// ---- the camera and the whole picture ---------------------------------------------------

CameraBasis cameraBasis(const Camera& camera) {
    dvec3 view = camera.target - camera.position;
    if (glm::length(view) == 0.0) throw Error("camera: target equals position, no view direction");
    CameraBasis basis;
    basis.position = camera.position;
    basis.forward = glm::normalize(view);
    dvec3 right = glm::cross(basis.forward, camera.up);
    // sin(angle between up and the view) below 1e-9: the roll is rounding
    // noise (and exactly parallel vectors give a zero cross product).
    if (glm::length(right) <= 1e-9 * glm::length(camera.up))
        throw Error("camera: up is parallel to the view direction, the roll is undefined");
    basis.right = glm::normalize(right);
    basis.up = glm::cross(basis.right, basis.forward);
    basis.fovYRadians = camera.fovYDegrees * kPi / 180.0;
    return basis;
}

namespace {

// n for spp = n*n; 0 when spp is not a positive square.
int samplesPerAxis(int spp) {
    int n = int(std::lround(std::sqrt(double(std::max(spp, 0)))));
    return (n >= 1 && n * n == spp) ? n : 0;
}

}  // namespace

dvec3 pixelRadiance(const Scene& scene, const CameraBasis& camera, int i, int j) {
    return pixelRadiance(scene, camera, i, j, EnvironmentOptions{});
}

dvec3 pixelRadiance(const Scene& scene, const CameraBasis& camera, int i, int j, const EnvironmentOptions& options) {
    const RenderSettings& settings = scene.render;
    int n = samplesPerAxis(settings.spp);
    dvec2 resolution(settings.width, settings.height);
    dvec3 sum(0.0);
    for (int s = 0; s < n * n; ++s) {
        dvec2 pixelSample = dvec2(i, j) + sampleOffset(s, n);
        dvec3 d = cameraRayDirection(pixelSample, resolution, camera.fovYRadians, camera.right, camera.up,
                                     camera.forward);
        sum += traceRadiance(scene, camera.position, d, options);
    }
    return sum / double(n * n);
}

Rendering renderCpu(const Scene& scene, int threads) { return renderCpu(scene, threads, EnvironmentOptions{}); }

Rendering renderCpu(const Scene& scene, int threads, const EnvironmentOptions& options) {
    const RenderSettings& settings = scene.render;
    const int width = settings.width;
    const int height = settings.height;
    if (width <= 0 || height <= 0)
        throw Error("renderCpu: image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not positive");
    if (samplesPerAxis(settings.spp) == 0)
        throw Error("renderCpu: spp = " + std::to_string(settings.spp) + " is not a square number");
    const CameraBasis camera = cameraBasis(scene.camera);

    Rendering out;
    out.radiance.width = out.display.width = width;
    out.radiance.height = out.display.height = height;
    out.radiance.rgb.assign(size_t(width) * height * 3, 0.0f);
    out.display.rgb.assign(size_t(width) * height * 3, 0);

    // Each worker takes the next unrendered row until none is left. Every
    // pixel is computed the same way whoever computes it, so the picture does
    // not depend on the number of threads.
    std::atomic<int> nextRow{0};
    auto worker = [&]() {
        for (int y = nextRow++; y < height; y = nextRow++) {
            int j = height - 1 - y;  // spec rows count from the bottom, images from the top
            for (int i = 0; i < width; ++i) {
                dvec3 L = pixelRadiance(scene, camera, i, j, options);
                dvec3 c = displayEncode(L, settings);
                float* radiance = out.radiance.at(i, y);
                std::uint8_t* display = out.display.at(i, y);
                for (int k = 0; k < 3; ++k) {
                    radiance[k] = float(L[k]);
                    display[k] = quantize8(c[k]);
                }
            }
        }
    };

    int count = threads > 0 ? threads : int(std::thread::hardware_concurrency());
    count = std::clamp(count, 1, height);  // hardware_concurrency() may say 0; more threads than rows idle
    std::vector<std::thread> pool;
    for (int k = 1; k < count; ++k) pool.emplace_back(worker);
    worker();  // the calling thread works too
    for (std::thread& t : pool) t.join();
    return out;
}

// ---- energy ------------------------------------------------------------------------------

namespace {

// A unit vector from its polar angle (as cos^2 theta) and azimuth, around n = +z.
dvec3 fromPolar(double cos2Theta, double phi) {
    double cosTheta = std::sqrt(std::clamp(cos2Theta, 0.0, 1.0));
    double sinTheta = std::sqrt(std::clamp(1.0 - cos2Theta, 0.0, 1.0));
    return dvec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

// Half vector for the stratified point (u1, u2) in (0,1)^2, distributed with
// density pdf(h) = D(h) NoH over solid angle (inverse CDF of the model's D),
// and that density, for the specular lobe of directionalAlbedo().
struct HalfVectorSample {
    dvec3 h;
    double pdf;
};

HalfVectorSample sampleHalfVector(double u1, double u2, const Material& m, const ShadingModel& model) {
    const dvec3 n(0.0, 0.0, 1.0);
    double alpha = ggxAlpha(m.roughness);
    double phi = 2.0 * kPi * u2;
    HalfVectorSample sample;
    if (model.blinnPhong) {
        // pdf = (s + 2)/(2 pi) NoH^(s + 1): the CDF of NoH is NoH^(s + 2).
        double s = shininessFromAlpha(alpha);
        double NoH = std::pow(u1, 1.0 / (s + 2.0));
        sample.h = fromPolar(NoH * NoH, phi);
        sample.pdf = (s + 2.0) / (2.0 * kPi) * std::pow(NoH, s + 1.0);
        return sample;
    }
    double tan2;
    if (model.distribution == DistributionModel::Beckmann) {
        tan2 = -alpha * alpha * std::log1p(-u1);  // Walter et al. 2007 eq. 28
        sample.h = fromPolar(1.0 / (1.0 + tan2), phi);
        sample.pdf = D_Beckmann(n, sample.h, alpha) * sample.h.z;
    } else {
        tan2 = alpha * alpha * u1 / (1.0 - u1);  // Walter et al. 2007 eq. 35
        sample.h = fromPolar(1.0 / (1.0 + tan2), phi);
        sample.pdf = D_GGX(n, sample.h, alpha) * sample.h.z;
    }
    return sample;
}

}  // namespace

dvec3 directionalAlbedo(double NoV, const Material& material, const ShadingModel& model, int samples) {
    const dvec3 n(0.0, 0.0, 1.0);
    const dvec3 v(std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), 0.0, NoV);
    const int N = std::max(samples, 1);
    dvec3 diffuse(0.0);
    dvec3 specular(0.0);
    for (int a = 0; a < N; ++a) {
        for (int b = 0; b < N; ++b) {
            double u1 = (a + 0.5) / N;  // cell centres: never 0 or 1, so no endpoint singularity
            double u2 = (b + 0.5) / N;

            // Diffuse lobe over cosine-distributed l (pdf NoL/pi): f NoL / pdf = f pi.
            dvec3 l = fromPolar(1.0 - u1, 2.0 * kPi * u2);
            diffuse += diffuseBRDF(n, v, l, material, model) * kPi;

            // Specular lobe over h ~ D NoH, l = reflect(-v, h), dl = 4 VoH dh.
            HalfVectorSample hs = sampleHalfVector(u1, u2, material, model);
            double VoH = glm::dot(v, hs.h);
            if (VoH <= 0.0 || hs.pdf <= 0.0) continue;  // h facing away from v maps to no l
            dvec3 lr = 2.0 * VoH * hs.h - v;
            double NoL = lr.z;
            if (NoL <= 0.0) continue;  // reflected below the horizon: not part of the integral
            specular += specularBRDF(n, v, lr, material, model) * (NoL * 4.0 * VoH / hs.pdf);
        }
    }
    return (diffuse + specular) / double(N * N);
}

dvec3 directionalAlbedo(double NoV, double roughness, dvec3 F0, double metallic, const ShadingModel& model,
                        int samples) {
    Material m;
    m.roughness = roughness;
    m.metallic = metallic;
    m.albedo = metallic > 0.0 ? glm::clamp((F0 - 0.04 * (1.0 - metallic)) / metallic, 0.0, 1.0) : dvec3(1.0);
    m.edgeTint = dvec3(1.0);
    return directionalAlbedo(NoV, m, model, samples);
}

}  // namespace rl::ref
