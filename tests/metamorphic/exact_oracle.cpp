#include "metamorphic/exact_oracle.h"

#include "core/light_surface.h"
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

namespace rl::meta {

namespace {

using glm::dvec3;
using Real = long double;

// A small long double vector: only what the geometry needs.
struct V {
    Real x = 0, y = 0, z = 0;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(Real s, V a) { return {s * a.x, s * a.y, s * a.z}; }
Real dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V normalized(V a) { return (1.0L / std::sqrt(dot(a, a))) * a; }
V widen(dvec3 v) { return {v.x, v.y, v.z}; }
dvec3 narrow(V v) { return dvec3(double(v.x), double(v.y), double(v.z)); }

struct OracleHit {
    int sphere = -1;
    bool inside = false;  // met from inside: n = -(p - c)/r
    V p, n;
};

// Roots of |o + t d - c| = r (unit d), stable form; false on a miss.
bool roots(V o, V d, const Sphere& s, Real& t0, Real& t1) {
    V c = widen(s.center);
    Real r = s.radius;
    V f = o - c;
    Real b = dot(f, d);
    V perpendicular = f - b * d;
    Real disc = r * r - dot(perpendicular, perpendicular);
    if (disc < 0) return false;
    Real q = -b - (b >= 0 ? 1.0L : -1.0L) * std::sqrt(disc);
    if (q == 0) {
        t0 = t1 = 0;
        return true;
    }
    t0 = (dot(f, f) - r * r) / q;
    t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

class Oracle {
public:
    explicit Oracle(const Scene& scene) : scene_(scene) {}

    // Sphere i has the surface of sphere `left` (the one a ray leaves): the
    // same sphere, or an identical one (same centre and radius, which
    // scenes/hard/overlapping.json has). Its surface passes through the ray
    // origin exactly, so it is handled exactly too: with no offset its
    // rounded root near 0 would decide, at random, whether it occludes.
    bool sameSurface(int i, int left) const {
        if (left < 0) return false;
        const Sphere& a = scene_.spheres[size_t(i)];
        const Sphere& b = scene_.spheres[size_t(left)];
        return i == left || (a.center == b.center && a.radius == b.radius);
    }

    // Nearest hit from o along unit d, `leaving` the sphere of `from` (or none).
    bool trace(V o, V d, const OracleHit* from, OracleHit& out) const {
        Real nearest = std::numeric_limits<Real>::infinity();
        int sphere = -1;
        bool inside = false;
        for (int i = 0; i < int(scene_.spheres.size()); ++i) {
            const Sphere& s = scene_.spheres[size_t(i)];
            if (from && sameSurface(i, from->sphere)) {
                if (!from->inside) continue;  // leaving the outside of a convex body: never again
                Real exit = std::max<Real>(-2 * dot(o - widen(s.center), d), 0);  // roots 0 and -2 f.d
                if (exit < nearest) nearest = exit, sphere = i, inside = true;
                continue;
            }
            Real t0, t1;
            if (!roots(o, d, s, t0, t1)) continue;
            if (t0 > 0 && t0 < nearest) nearest = t0, sphere = i, inside = false;
            else if (t0 <= 0 && t1 > 0 && t1 < nearest) nearest = t1, sphere = i, inside = true;
        }
        if (sphere < 0) return false;
        const Sphere& s = scene_.spheres[size_t(sphere)];
        out.sphere = sphere;
        out.inside = inside;
        out.p = o + nearest * d;
        V u = normalized(out.p - widen(s.center));
        out.n = inside ? Real(-1) * u : u;
        return true;
    }

    // A light on a sphere's surface (lightSurfaceSide() == 0, the model's
    // rule: docs/model.md, "A light on a surface") is hidden by that sphere
    // only where the segment enters it before the light.
    bool lightReachable(const OracleHit& hit, const dvec3& lightPosition) const {
        V light = widen(lightPosition);
        V toLight = light - hit.p;
        Real distance = std::sqrt(dot(toLight, toLight));
        if (distance == 0) return true;
        V d = (1 / distance) * toLight;
        for (int i = 0; i < int(scene_.spheres.size()); ++i) {
            const Sphere& s = scene_.spheres[size_t(i)];
            bool onSurface = lightSurfaceSide(lightPosition, s) == 0;
            if (sameSurface(i, hit.sphere)) {
                if (hit.inside && !onSurface && -2 * dot(hit.p - widen(s.center), d) < distance) return false;
                continue;
            }
            Real t0, t1;
            if (!roots(hit.p, d, s, t0, t1)) continue;
            if (onSurface) {
                if (t0 > 0 && dot(d, light - widen(s.center)) > 0) return false;
                continue;
            }
            if ((t0 > 0 && t0 < distance) || (t1 > 0 && t1 < distance)) return false;
        }
        return true;
    }

    dvec3 shade(const OracleHit& hit, dvec3 v) const {
        const Material& m = scene_.spheres[size_t(hit.sphere)].material;
        dvec3 p = narrow(hit.p), n = narrow(hit.n);
        dvec3 radiance(0.0);
        for (const Light& light : scene_.lights) {
            dvec3 E = ref::pointLightIrradiance(p, n, light.position, light.color * light.intensity);
            if (E == dvec3(0.0) || !lightReachable(hit, light.position)) continue;
            dvec3 l = narrow(normalized(widen(light.position) - hit.p));
            radiance += ref::cookTorranceBRDF(n, v, l, m, scene_.model) * E;
        }
        return radiance + scene_.render.ambient * m.albedo * m.ao;
    }

    dvec3 radiance(V origin, V dir) const {
        dvec3 sum(0.0), throughput(1.0);
        OracleHit hit;
        bool found = trace(origin, dir, nullptr, hit);
        for (int bounce = 0;; ++bounce) {
            if (!found) {
                sum += throughput * scene_.render.background;
                break;
            }
            sum += throughput * shade(hit, narrow(Real(-1) * dir));
            if (bounce == scene_.render.maxBounces) break;
            const Material& m = scene_.spheres[size_t(hit.sphere)].material;
            double NoV = std::clamp(double(-dot(hit.n, dir)), ref::kMinNoV, 1.0);
            throughput *= ref::F_SchlickRoughness(ref::baseReflectance(m), NoV, m.roughness);
            dir = normalized(dir - (2 * dot(dir, hit.n)) * hit.n);  // reflect(d, n)
            OracleHit next;
            found = trace(hit.p, dir, &hit, next);
            hit = next;
        }
        return sum;
    }

private:
    const Scene& scene_;
};

}  // namespace

Rendering renderOracle(const Scene& scene, int threads) {
    const RenderSettings& settings = scene.render;
    const int width = settings.width, height = settings.height;
    const int n = int(std::lround(std::sqrt(double(settings.spp))));
    const Camera& camera = scene.camera;
    // The camera basis and the ray directions in long double too (spec "Camera").
    V forward = normalized(widen(camera.target - camera.position));
    V upIn = widen(camera.up);
    V right = normalized({forward.y * upIn.z - forward.z * upIn.y, forward.z * upIn.x - forward.x * upIn.z,
                          forward.x * upIn.y - forward.y * upIn.x});
    V up = {right.y * forward.z - right.z * forward.y, right.z * forward.x - right.x * forward.z,
            right.x * forward.y - right.y * forward.x};
    Real tanHalf = std::tan(Real(camera.fovYDegrees) * 3.14159265358979323846264338327950288L / 360);
    Real aspect = Real(width) / Real(height);
    V origin = widen(camera.position);
    Oracle oracle(scene);

    Rendering out;
    out.radiance.width = out.display.width = width;
    out.radiance.height = out.display.height = height;
    out.radiance.rgb.assign(size_t(width) * height * 3, 0.0f);
    out.display.rgb.assign(size_t(width) * height * 3, 0);
    std::atomic<int> nextRow{0};
    auto worker = [&]() {
        for (int y = nextRow++; y < height; y = nextRow++) {
            int j = height - 1 - y;
            for (int i = 0; i < width; ++i) {
                dvec3 sum(0.0);
                for (int s = 0; s < n * n; ++s) {
                    Real sx = (Real(s % n) + 0.5L) / n, sy = (Real(s / n) + 0.5L) / n;
                    Real x = (2 * (i + sx) / width - 1) * tanHalf * aspect;
                    Real yy = (2 * (j + sy) / height - 1) * tanHalf;
                    sum += oracle.radiance(origin, normalized(x * right + yy * up + forward));
                }
                dvec3 L = sum / double(n * n);
                dvec3 c = ref::displayEncode(L, settings);
                for (int k = 0; k < 3; ++k) {
                    out.radiance.at(i, y)[k] = float(L[k]);
                    out.display.at(i, y)[k] = quantize8(c[k]);
                }
            }
        }
    };
    int count = std::clamp(threads > 0 ? threads : int(std::thread::hardware_concurrency()), 1, height);
    std::vector<std::thread> pool;
    for (int k = 1; k < count; ++k) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return out;
}

}  // namespace rl::meta
