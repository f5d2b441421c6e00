#include "reference/pixel_breakdown.h"

#include "core/error.h"
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"
#include "reference/sphere_form_factor.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace rl::ref {
namespace {

using glm::dvec3;

double modelD(const ShadingModel& m, dvec3 n, dvec3 h, double alpha) {
    return m.distribution == DistributionModel::Beckmann ? D_Beckmann(n, h, alpha) : D_GGX(n, h, alpha);
}
double modelG(const ShadingModel& m, double NoV, double NoL, const Material& mat) {
    switch (m.geometry) {
        case GeometryModel::SmithGGXSeparable: return G_SmithGGXSeparable(NoV, NoL, ggxAlpha(mat.roughness));
        case GeometryModel::SmithGGXCorrelated: return G_SmithGGXCorrelated(NoV, NoL, ggxAlpha(mat.roughness));
        default: return G_SchlickGGX(NoV, NoL, mat.roughness);
    }
}
dvec3 modelF(const ShadingModel& m, const Material& mat, double VoH) {
    switch (m.fresnel) {
        case FresnelModel::Dielectric: return F_Dielectric(baseReflectance(mat), VoH);
        case FresnelModel::Conductor: return F_Conductor(baseReflectance(mat), mat.edgeTint, VoH);
        default: return F_Schlick(baseReflectance(mat), VoH);
    }
}

LightTerms lightTerms(const Scene& scene, const Hit& hit, dvec3 v, int index) {
    const Light& light = scene.lights[std::size_t(index)];
    const Material& m = scene.spheres[std::size_t(hit.sphere)].material;
    LightTerms t;
    t.light = index;
    const dvec3 toLight = light.position - hit.p;
    t.distance = glm::length(toLight);
    t.l = t.distance > 0 ? toLight / t.distance : hit.n;
    t.h = glm::normalize(t.l + v);
    t.NoL = std::clamp(glm::dot(hit.n, t.l), 0.0, 1.0);
    t.NoH = glm::dot(hit.n, t.h);
    t.VoH = glm::dot(v, t.h);
    const double NoV = std::clamp(glm::dot(hit.n, v), kMinNoV, 1.0);
    t.D = modelD(scene.model, hit.n, t.h, ggxAlpha(m.roughness));
    t.G = modelG(scene.model, NoV, t.NoL, m);
    t.F = modelF(scene.model, m, t.VoH);
    t.E = pointLightIrradiance(hit.p, hit.n, light.position, light.color * light.intensity);
    // As directLight(): no shadow ray where the light adds nothing.
    t.facesAway = t.E == dvec3(0.0);
    if (t.facesAway) return t;
    t.shadowed = !lightReachable(scene, hit, light.position);  // the renderer's shadow ray
    if (t.shadowed) return t;
    t.diffuse = diffuseBRDF(hit.n, v, t.l, m, scene.model) * t.E;
    t.specular = specularBRDF(hit.n, v, t.l, m, scene.model) * t.E;
    return t;
}

// shaders/environment.glsl's splitSumLookup(), in double.
glm::dvec2 splitSumAt(const EnvironmentTables& t, double NoV, double roughness) {
    const int size = t.tableSize;
    const double r = std::clamp(roughness, kMinRoughness, 1.0);
    const double px = std::clamp(NoV * size - 0.5, 0.0, double(size - 1)),
                 py = std::clamp(r * size - 0.5, 0.0, double(size - 1));
    const int x0 = int(std::floor(px)), y0 = int(std::floor(py));
    const int x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
    const double ax = px - x0, ay = py - y0;
    auto at = [&t, size](int x, int y) { return (*t.table)[std::size_t(y * size + x)]; };
    return glm::mix(glm::mix(at(x0, y0), at(x1, y0), ax), glm::mix(at(x0, y1), at(x1, y1), ax), ay);
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}
std::string vec(dvec3 v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

}  // namespace

EnvironmentTerms environmentTerms(const Environment& environment, const EnvironmentTables& tables, dvec3 n, dvec3 v,
                                  const Material& m, const ShadingModel& model) {
    EnvironmentTerms e;
    const double NoV = std::clamp(glm::dot(n, v), kMinNoV, 1.0);
    e.irradiance = environmentIrradianceSh9(environment, *tables.sh, n);
    const int levels = int(tables.levels->size());
    e.level = std::clamp(m.roughness, 0.0, 1.0) * double(levels - 1);
    const dvec3 r = environmentLocalDirection(environment, glm::reflect(-v, n));
    const double l = std::clamp(e.level, 0.0, double(levels - 1));
    const int k0 = int(std::floor(l)), k1 = std::min(k0 + 1, levels - 1);
    auto lookup = [&](dvec3 d) {
        const glm::dvec2 uv = equirectUv(d);
        return environment.intensity * glm::mix(bilinearRadiance((*tables.levels)[std::size_t(k0)], uv.x, uv.y),
                                                bilinearRadiance((*tables.levels)[std::size_t(k1)], uv.x, uv.y),
                                                l - double(k0));
    };
    e.prefiltered = lookup(r);
    // Turned by kLookupAngle four ways, across r.
    const dvec3 a = glm::normalize(glm::cross(r, std::abs(r.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0)));
    const dvec3 b = glm::cross(r, a);
    for (const dvec3& t : {a, -a, b, -b})
        e.prefilteredSpread = glm::max(e.prefilteredSpread, glm::abs(lookup(glm::normalize(r + kLookupAngle * t)) - e.prefiltered));
    e.scaleBias = splitSumAt(tables, NoV, m.roughness);
    const dvec3 F0 = baseReflectance(m);
    const dvec3 specular = e.prefiltered * (F0 * e.scaleBias.x + e.scaleBias.y);
    const dvec3 diffuseWeight = (1.0 - m.metallic) * (1.0 - F0) * m.albedo / kPi;
    // Two irradiances (shaders/environment.glsl), both clamped at 0: the
    // debugger's, SH9's with the sun's three bands swapped for the sun as a
    // point source (sunIrradianceCorrection), and the picture's, SH9's with
    // the bands taken out, the sun a light of its own (sunLight; in the
    // image's frame here).
    dvec3 irradiance = e.irradiance, sunless = e.irradiance, sun(0.0);
    if (tables.sunPresent) {
        const dvec3 s = tables.sunDirection, nl = environmentLocalDirection(environment, n);
        const double x = glm::dot(nl, s);
        const dvec3 bands = environment.intensity * tables.sunPower * (0.25 + 0.5 * x + 0.3125 * (1.5 * x * x - 0.5));
        irradiance += environment.intensity * tables.sunPower * std::max(x, 0.0) - bands;
        sunless -= bands;
        if (x > 0.0) {
            // The BRDF's mean over the sun's disc, as sunLight
            // (shaders/environment.glsl) reads it: at the disc's centre with
            // the widened lobe where alpha >= theta_s, towards the disc's
            // point nearest r below theta_s / 2 (SUN_DISC_* there), mixed
            // between.
            constexpr double kPointBelow = 0.5, kCentreFrom = 1.0;
            const dvec3 vl = environmentLocalDirection(environment, v);
            const double rough = std::clamp(m.roughness, kMinRoughness, 1.0);
            Material wide = m;
            wide.roughness = std::sqrt(std::min(std::hypot(rough * rough, 0.5 * tables.sunAngularRadius), 1.0));
            const double t = std::clamp((rough * rough / tables.sunAngularRadius - kPointBelow) / (kCentreFrom - kPointBelow), 0.0, 1.0);
            const double centre = t * t * (3.0 - 2.0 * t);  // GLSL's smoothstep
            dvec3 f = centre > 0.0 ? cookTorranceBRDF(nl, vl, s, wide, model) : dvec3(0.0);
            if (centre < 1.0) {
                const double apart = std::acos(std::clamp(glm::dot(r, s), -1.0, 1.0));
                dvec3 l = s;
                if (apart > 1e-6) {
                    const double a = std::min(apart, tables.sunAngularRadius);
                    l = std::cos(a) * s + std::sin(a) * glm::normalize(r - glm::dot(r, s) * s);
                }
                const dvec3 narrow = glm::min(cookTorranceBRDF(nl, vl, l, m, model), cookTorranceBRDF(nl, vl, l, wide, model));
                f = narrow + (f - narrow) * centre;
            }
            sun = f * environment.intensity * tables.sunPower * x;
        }
    }
    e.light = diffuseWeight * glm::max(irradiance, dvec3(0.0)) + specular;
    e.pictureLight = diffuseWeight * glm::max(sunless, dvec3(0.0)) + specular + sun;
    return e;
}

PixelTerms explainPixel(const Scene& scene, const Camera& camera, int width, int height, int i, int j,
                        const EnvironmentTables* environment) {
    const bool withEnvironment = environment && scene.environment;
    if (i < 0 || j < 0 || i >= width || j >= height)
        throw Error("pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") is outside the " +
                    std::to_string(width) + "x" + std::to_string(height) + " picture");
    PixelTerms out;
    out.i = i;
    out.j = j;
    out.height = height;
    const CameraBasis basis = cameraBasis(camera);
    dvec3 dir = cameraRayDirection(glm::dvec2(i + 0.5, j + 0.5), glm::dvec2(width, height), basis.fovYRadians,
                                   basis.right, basis.up, basis.forward);
    dvec3 origin = basis.position;
    dvec3 throughput(1.0);
    // traceRadiance(), step by step (cpu_reference.cpp): the camera ray with
    // closestHit(), every bounce with nextHit() from the hit it leaves.
    Hit hit;
    bool found = closestHit(scene, origin, dir, hit);
    for (int depth = 0; depth <= scene.render.maxBounces; ++depth) {
        BounceTerms b;
        b.depth = depth;
        b.origin = origin;
        b.dir = dir;
        b.throughput = throughput;
        if (!found) {
            // With the environment: the camera ray sees it, an escaping bounce
            // adds nothing (its direction is in the hit's environment light).
            b.contribution = !withEnvironment ? throughput * scene.render.background
                             : depth == 0     ? rl::environmentRadiance(*scene.environment, dir)
                                              : dvec3(0.0);
            out.radiance += b.contribution;
            out.chain.push_back(b);
            break;
        }
        const Material& m = scene.spheres[std::size_t(hit.sphere)].material;
        b.hit = true;
        b.sphere = hit.sphere;
        b.material = m;
        b.p = hit.p;
        b.n = hit.n;
        b.t = hit.t;
        b.v = -dir;
        for (int l = 0; l < int(scene.lights.size()); ++l) b.lights.push_back(lightTerms(scene, hit, b.v, l));
        b.ambient = scene.render.ambient * m.albedo * m.ao;
        b.shaded = shadeHit(scene, hit, b.v);
        if (withEnvironment) {
            b.environment = environmentTerms(*scene.environment, *environment, hit.n, b.v, m, scene.model);
            b.environment->formFactors = summedFormFactors(scene.spheres, hit.sphere, hit.p, hit.n);
            b.shaded += b.environment->pictureLight;
        }
        b.contribution = throughput * b.shaded;
        out.radiance += b.contribution;
        b.NoV = std::clamp(glm::dot(hit.n, b.v), kMinNoV, 1.0);
        b.Fr = F_SchlickRoughness(baseReflectance(m), b.NoV, m.roughness);
        throughput *= b.Fr;
        out.chain.push_back(b);
        if (depth == scene.render.maxBounces) break;
        origin = hit.p;  // the bounce leaves this surface; nextHit() handles its sphere exactly
        dir = glm::normalize(glm::reflect(dir, hit.n));
        Hit next;
        found = nextHit(scene, hit, dir, next);
        hit = next;
    }
    Scene atSize = scene;
    atSize.render.width = width;
    atSize.render.height = height;
    out.pixelRadiance = pixelRadiance(atSize, basis, i, j);
    out.display = displayEncode(out.pixelRadiance, scene.render);
    return out;
}

std::string formatPixelTerms(const Scene& scene, const PixelTerms& t) {
    std::ostringstream s;
    s << "pixel (" << t.i << ", " << (t.height > 0 ? t.height - 1 - t.j : t.j) << ") from the "
      << (t.height > 0 ? "top" : "bottom") << " left, CPU reference (double), the centre ray:\n";
    for (const BounceTerms& b : t.chain) {
        const std::string at = b.depth == 0 ? "primary hit" : "bounce " + std::to_string(b.depth);
        s << at << ": throughput " << vec(b.throughput) << "\n";
        if (!b.hit) {
            s << "  no hit: background " << vec(scene.render.background) << ", contribution " << vec(b.contribution)
              << "\n";
            continue;
        }
        const Material& m = b.material;
        s << "  spheres[" << b.sphere << "] (of " << scene.spheres.size() << "): albedo " << vec(m.albedo)
          << ", roughness " << num(m.roughness) << ", metallic " << num(m.metallic) << ", ao " << num(m.ao) << "\n";
        s << "  t " << num(b.t) << "  p " << vec(b.p) << "  n " << vec(b.n) << "  v " << vec(b.v) << "\n";
        for (const LightTerms& l : b.lights) {
            s << "  lights[" << l.light << "]: l " << vec(l.l) << "  h " << vec(l.h) << "\n";
            s << "    NoL " << num(l.NoL) << "  NoH " << num(l.NoH) << "  VoH " << num(l.VoH) << "  D " << num(l.D)
              << "  G " << num(l.G) << "  F " << vec(l.F) << "\n";
            s << "    E " << vec(l.E) << (l.facesAway ? "  faces away (no light)" : l.shadowed ? "  SHADOWED" : "  lit")
              << "  diffuse " << vec(l.diffuse) << "  specular " << vec(l.specular) << "\n";
        }
        if (b.environment) {
            const EnvironmentTerms& e = *b.environment;
            s << "  environment: irradiance " << vec(e.irradiance) << "  level " << num(e.level) << "  prefiltered "
              << vec(e.prefiltered) << "\n    scale " << num(e.scaleBias.x) << "  bias " << num(e.scaleBias.y)
              << "  form factors " << num(e.formFactors) << "  light " << vec(e.light) << "\n";
        }
        s << "  ambient " << vec(b.ambient) << "  shaded " << vec(b.shaded) << "  contribution " << vec(b.contribution)
          << "\n";
        s << "  NoV " << num(b.NoV) << "  Fr " << vec(b.Fr) << " (the next throughput factor)\n";
    }
    s << "radiance " << vec(t.radiance) << " (centre ray)  pixel " << vec(t.pixelRadiance) << " ("
      << scene.render.spp << " spp)  display " << vec(t.display) << "\n";
    return s.str();
}

}  // namespace rl::ref
