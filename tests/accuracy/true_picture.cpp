#include "accuracy/true_picture.h"

#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::acc {

using glm::dvec3;

namespace {

struct TrueTracer {
    const Scene& scene;

    // Distance to sphere i from o along unit d; the sphere `leaving` (o lies
    // on it) exactly: none from outside, the far root -2 (o - c).d from inside.
    double sphereHit(dvec3 o, dvec3 d, int i, int leaving) const {
        const Sphere& s = scene.spheres[i];
        if (i != leaving) return ref::intersectSphere(o, d, s.center, s.radius);
        double b = glm::dot(o - s.center, d);
        return b >= 0.0 ? ref::kNoHit : -2.0 * b;
    }

    int closest(dvec3 o, dvec3 d, int leaving, double& tHit) const {
        int sphere = -1;
        tHit = 1e300;
        for (int i = 0; i < int(scene.spheres.size()); ++i) {
            double t = sphereHit(o, d, i, leaving);
            if (t > 0.0 && t < tHit) {
                tHit = t;
                sphere = i;
            }
        }
        return sphere;
    }

    bool occluded(dvec3 o, dvec3 d, double tMax, int leaving) const {
        for (int i = 0; i < int(scene.spheres.size()); ++i) {
            double t = sphereHit(o, d, i, leaving);
            if (t > 0.0 && t < tMax) return true;
        }
        return false;
    }

    // "Near-zero" offset for the *other* spheres: 2^-40 of the numbers behind
    // p (1e-12 at scale 1), far below any pixel, but past double's rounding
    // of p (2^-52 of them), so a sphere that coincides with or touches the
    // one p lies on (two identical spheres) does not shadow it at random.
    static dvec3 offset(dvec3 p, dvec3 n, const Sphere& s) {
        auto maxAbs = [](dvec3 v) { return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))); };
        return p + n * (std::ldexp(1.0, -40) * std::max(maxAbs(p), maxAbs(s.center) + s.radius));
    }

    dvec3 trace(dvec3 origin, dvec3 dir) const {
        dvec3 radiance(0.0), throughput(1.0);
        int leaving = -1;
        for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce) {
            dir = glm::normalize(dir);  // a reflected direction drifts from unit length
            double t;
            int i = closest(origin, dir, leaving, t);
            if (i < 0) {
                radiance += throughput * scene.render.background;
                break;
            }
            const Sphere& s = scene.spheres[i];
            dvec3 outward = glm::normalize(origin + t * dir - s.center);
            dvec3 p = s.center + s.radius * outward;  // exactly on the sphere, to double's rounding
            dvec3 n = glm::dot(outward, dir) > 0.0 ? -outward : outward;
            dvec3 v = -dir;
            const Material& m = s.material;
            dvec3 direct(0.0);
            for (const Light& light : scene.lights) {
                dvec3 E = ref::pointLightIrradiance(p, n, light.position, light.color * light.intensity);
                if (E == dvec3(0.0)) continue;
                dvec3 toLight = light.position - p;
                double distance = glm::length(toLight);
                if (occluded(offset(p, n, s), toLight / distance, distance, i)) continue;
                direct += ref::cookTorranceBRDF(n, v, toLight / distance, m, scene.model) * E;
            }
            radiance += throughput * (direct + scene.render.ambient * m.albedo * m.ao);
            double NoV = std::clamp(glm::dot(n, v), ref::kMinNoV, 1.0);
            throughput *= ref::F_SchlickRoughness(ref::baseReflectance(m), NoV, m.roughness);
            origin = offset(p, n, s);
            dir = glm::reflect(dir, n);
            leaving = i;
        }
        return radiance;
    }
};

}  // namespace

Rendering renderTruePicture(const Scene& scene) {
    const RenderSettings& settings = scene.render;
    ref::CameraBasis camera = ref::cameraBasis(scene.camera);
    TrueTracer tracer{scene};
    int n = int(std::lround(std::sqrt(double(settings.spp))));
    Rendering out;
    out.radiance.width = out.display.width = settings.width;
    out.radiance.height = out.display.height = settings.height;
    out.radiance.rgb.assign(std::size_t(settings.width) * settings.height * 3, 0.0f);
    out.display.rgb.assign(std::size_t(settings.width) * settings.height * 3, 0);
    glm::dvec2 resolution(settings.width, settings.height);
    for (int y = 0; y < settings.height; ++y) {
        int j = settings.height - 1 - y;
        for (int i = 0; i < settings.width; ++i) {
            dvec3 sum(0.0);
            for (int s = 0; s < n * n; ++s) {
                glm::dvec2 sample = glm::dvec2(i, j) + ref::sampleOffset(s, n);
                dvec3 d = ref::cameraRayDirection(sample, resolution, camera.fovYRadians, camera.right, camera.up,
                                                  camera.forward);
                sum += tracer.trace(camera.position, d);
            }
            dvec3 L = sum / double(n * n);
            dvec3 c = ref::displayEncode(L, settings);
            for (int k = 0; k < 3; ++k) {
                out.radiance.at(i, y)[k] = float(L[k]);
                out.display.at(i, y)[k] = quantize8(c[k]);
            }
        }
    }
    return out;
}

}  // namespace rl::acc
