// environment_reference.cpp: the exact (Monte Carlo) environment light of
// the CPU reference; see environment_reference.h.
#include "reference/environment_reference.h"

#include "reference/brdf_reference.h"
#include "reference/sh9.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>

namespace rl::ref {

using glm::dvec3;

// ---- randomness ------------------------------------------------------------------

std::uint64_t Random::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double Random::uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }

std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b) {
    Random r(a ^ (b * 0xD6E8FEB86659FD93ull + 0x632BE59BD9B4E019ull));
    return r.next();
}

// ---- sampling the radiance map -----------------------------------------------------

namespace {

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

// An orthonormal basis around the unit n (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited").
void basisAround(dvec3 n, dvec3& t, dvec3& b) {
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    t = dvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = dvec3(c, sign + n.y * n.y * a, -n.y);
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const RadianceImage& image) : width_(image.width), height_(image.height) {
    const double pi = kPi;
    cosTop_.resize(size_t(height_) + 1);
    for (int y = 0; y <= height_; ++y) cosTop_[size_t(y)] = std::cos(pi * y / height_);
    cosTop_[0] = 1.0;
    cosTop_[size_t(height_)] = -1.0;
    const size_t count = size_t(width_) * size_t(height_);
    std::vector<double> weight(count);
    double mean = 0.0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            double solidAngle = 2.0 * pi / width_ * (cosTop_[size_t(y)] - cosTop_[size_t(y) + 1]);
            double l = luminance(image.at(x, y));
            weight[size_t(y) * width_ + x] = l;
            mean += l * solidAngle;
        }
    mean /= 4.0 * pi;
    // Black image: uniform over the sphere.
    double floor = mean > 0.0 ? 0.01 * mean : 1.0;
    cdf_.resize(count);
    density_.resize(count);
    double total = 0.0;
    for (int y = 0; y < height_; ++y) {
        double solidAngle = 2.0 * pi / width_ * (cosTop_[size_t(y)] - cosTop_[size_t(y) + 1]);
        for (int x = 0; x < width_; ++x) {
            size_t k = size_t(y) * width_ + x;
            weight[k] = (weight[k] + floor) * solidAngle;
            total += weight[k];
            cdf_[k] = total;
        }
    }
    for (size_t k = 0; k < count; ++k) {
        int y = int(k / size_t(width_));
        double solidAngle = 2.0 * pi / width_ * (cosTop_[size_t(y)] - cosTop_[size_t(y) + 1]);
        cdf_[k] /= total;
        density_[k] = weight[k] / total / solidAngle;  // probability of the pixel over its solid angle
    }
    cdf_.back() = 1.0;
}

EnvironmentSampler::Sample EnvironmentSampler::sample(double u1, double u2, double u3) const {
    size_t k = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u1) - cdf_.begin());
    k = std::min(k, cdf_.size() - 1);
    while (density_[k] == 0.0 && k + 1 < cdf_.size()) ++k;  // never: every weight is > 0
    int x = int(k % size_t(width_));
    int y = int(k / size_t(width_));
    // Uniform in solid angle inside the pixel: phi uniform, cos(theta) uniform.
    double u = (x + u2) / width_;
    double cosTheta = cosTop_[size_t(y)] + (cosTop_[size_t(y) + 1] - cosTop_[size_t(y)]) * u3;
    double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    double phi = (u - 0.5) * 2.0 * kPi;
    Sample s;
    s.direction = dvec3(sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi));
    s.pdf = density_[k];
    return s;
}

double EnvironmentSampler::pdf(dvec3 d) const { return pdf(equirectUv(d), d.y); }

double EnvironmentSampler::pdf(glm::dvec2 uv, double cosTheta) const {
    int x = std::clamp(int(uv.x * width_), 0, width_ - 1);
    // The row from cos(theta) against the edges (the same numbers sample() used).
    double c = std::clamp(cosTheta, -1.0, 1.0);
    int y = std::clamp(int(uv.y * height_), 0, height_ - 1);
    while (y > 0 && c > cosTop_[size_t(y)]) --y;
    while (y + 1 < height_ && c < cosTop_[size_t(y) + 1]) ++y;
    return density_[size_t(y) * width_ + x];
}

std::shared_ptr<const EnvironmentSampler> environmentSampler(const Environment& environment) {
    static std::mutex mutex;
    static std::map<const RadianceImage*, std::pair<std::weak_ptr<const RadianceImage>,
                                                     std::shared_ptr<const EnvironmentSampler>>> cache;
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = cache.begin(); it != cache.end();)  // forget the samplers of images that are gone
        it = it->second.first.expired() ? cache.erase(it) : std::next(it);
    auto& entry = cache[environment.image.get()];
    if (!entry.second || entry.first.lock() != environment.image) {
        entry.first = environment.image;
        entry.second = std::make_shared<const EnvironmentSampler>(*environment.image);
    }
    return entry.second;
}

// ---- the estimate ------------------------------------------------------------------

namespace {

// Below this n.v the specular draws use D(h) n.h half vectors instead of
// visible normals (whose pdf divides by n.v).
constexpr double kMinVisibleNoV = 1e-4;

// pdf per steradian of drawing l from the BRDF's mixture: the specular share
// by GGX visible normals (Heitz 2018: G1(v) D(h) / (4 n.v), G1 Smith's for
// GGX; D(h) n.h / (4 v.h) below kMinVisibleNoV), the rest by the cosine lobe.
double brdfPdf(dvec3 n, dvec3 v, dvec3 l, const SurfaceBrdf& brdf) {
    double NoL = glm::dot(n, l);
    if (NoL <= 0.0) return 0.0;
    double pdf = (1.0 - brdf.specularShare) * NoL / kPi;
    if (brdf.specularShare > 0.0) {
        dvec3 h = v + l;
        double length = glm::length(h);
        if (length > 0.0) {
            h /= length;
            double VoH = glm::dot(v, h);
            double NoH = glm::dot(n, h);
            double NoV = glm::dot(n, v);
            if (VoH > 0.0 && NoH > 0.0) {
                double D = D_GGX(n, h, brdf.alpha);
                pdf += brdf.specularShare * (NoV >= kMinVisibleNoV ? G1_SmithGGX(NoV, brdf.alpha) * D / (4.0 * NoV)
                                                                    : D * NoH / (4.0 * VoH));
            }
        }
    }
    return pdf;
}

// A GGX visible normal for the view ve in the frame where n = +z (Heitz
// 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)).
dvec3 visibleNormal(dvec3 ve, double alpha, double u1, double u2) {
    dvec3 vh = glm::normalize(dvec3(alpha * ve.x, alpha * ve.y, ve.z));
    double lengthSquared = vh.x * vh.x + vh.y * vh.y;
    dvec3 t1 = lengthSquared > 0.0 ? dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lengthSquared) : dvec3(1.0, 0.0, 0.0);
    dvec3 t2 = glm::cross(vh, t1);
    double r = std::sqrt(u1);
    double phi = 2.0 * kPi * u2;
    double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
}

// A direction drawn from the BRDF's mixture (may lie below the surface: a
// GGX half vector can reflect v under the horizon; such a draw adds nothing).
dvec3 drawFromBrdf(dvec3 n, dvec3 v, const SurfaceBrdf& brdf, Random& random) {
    dvec3 t, b;
    basisAround(n, t, b);
    double choose = random.uniform();
    double u1 = random.uniform(), u2 = random.uniform();
    double phi = 2.0 * kPi * u2;
    if (choose < brdf.specularShare) {
        dvec3 h;
        dvec3 ve(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n));
        if (ve.z >= kMinVisibleNoV) {
            dvec3 he = visibleNormal(ve, brdf.alpha, u1, u2);
            h = he.x * t + he.y * b + he.z * n;
        } else {
            double a2 = brdf.alpha * brdf.alpha;
            double cos2 = (1.0 - u1) / (1.0 + (a2 - 1.0) * u1);  // Walter et al. 2007 eq. 35, 1/(1 + tan^2)
            double cosTheta = std::sqrt(std::max(0.0, cos2));
            double sinTheta = std::sqrt(std::max(0.0, 1.0 - cos2));
            h = sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * n;
        }
        return glm::normalize(2.0 * glm::dot(v, h) * h - v);
    }
    double cosTheta = std::sqrt(1.0 - u1);  // pdf cos/pi (Malley's method)
    double sinTheta = std::sqrt(u1);
    return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * n;
}

}  // namespace

dvec3 integrateEnvironmentLight(const Environment& environment, const EnvironmentSampler& sampler, dvec3 n,
                                dvec3 v, const SurfaceBrdf& brdf, const std::function<bool(dvec3 l)>& escapes,
                                int samples, Random& random) {
    dvec3 sum(0.0);
    const int N = std::max(samples, 1);
    // One direction l drawn by either strategy adds f L n.l / (pdf_brdf + pdf_map):
    // the balance heuristic with equal counts (Veach 1997, eq. 9.10).
    auto add = [&](dvec3 l) {
        double NoL = glm::dot(n, l);
        if (NoL <= 0.0) return;
        dvec3 local = environmentLocalDirection(environment, l);
        glm::dvec2 uv = equirectUv(local);
        double pdfMap = sampler.pdf(uv, local.y);
        double pdfBrdf = brdfPdf(n, v, l, brdf);
        double denominator = pdfMap + pdfBrdf;
        if (!(denominator > 0.0)) return;
        dvec3 f = brdf.f(l);
        if (f == dvec3(0.0)) return;
        dvec3 L = environment.intensity * bilinearRadiance(*environment.image, uv.x, uv.y);
        if (L == dvec3(0.0)) return;
        if (escapes && !escapes(l)) return;
        sum += f * L * (NoL / denominator);
    };
    for (int k = 0; k < N; ++k) {
        add(drawFromBrdf(n, v, brdf, random));
        double u1 = random.uniform(), u2 = random.uniform(), u3 = random.uniform();
        add(environmentWorldDirection(environment, sampler.sample(u1, u2, u3).direction));
    }
    return sum / double(N);
}

SurfaceBrdf sceneBrdf(const Scene& scene, const Hit& hit, dvec3 v) {
    const Material& m = scene.spheres[size_t(hit.sphere)].material;
    const ShadingModel model = scene.model;
    const dvec3 n = hit.n;
    SurfaceBrdf brdf;
    brdf.f = [n, v, m, model](dvec3 l) { return cookTorranceBRDF(n, v, l, m, model); };
    brdf.alpha = ggxAlpha(m.roughness);
    // Rough weights of the lobes at n.v: Fresnel's share goes to the
    // specular lobe, what passes it to the diffuse one; at least 10% each
    // (both strategies stay useful), all to GGX for a pure metal.
    double NoV = std::clamp(glm::dot(n, v), kMinNoV, 1.0);
    dvec3 F = F_Schlick(baseReflectance(m), NoV);
    double specular = (F.x + F.y + F.z) / 3.0;
    double diffuse = (1.0 - specular) * (1.0 - m.metallic) * (m.albedo.x + m.albedo.y + m.albedo.z) / 3.0;
    brdf.specularShare = m.metallic >= 1.0 ? 1.0 : std::clamp(specular / (specular + diffuse), 0.1, 0.9);
    return brdf;
}

dvec3 environmentLight(const Scene& scene, const Hit& hit, dvec3 v, const EnvironmentOptions& options,
                       std::uint64_t seed) {
    if (!scene.environment) return dvec3(0.0);
    const Environment& environment = *scene.environment;
    std::shared_ptr<const EnvironmentSampler> sampler = environmentSampler(environment);
    Random random(seed);
    std::function<bool(dvec3)> escapes;
    if (options.visibility)
        escapes = [&scene, &hit](dvec3 l) {
            Hit blocker;
            return !nextHit(scene, hit, l, blocker);
        };
    return integrateEnvironmentLight(environment, *sampler, hit.n, v, sceneBrdf(scene, hit, v), escapes,
                                     options.samples, random);
}

// ---- SH irradiance (sh9.h): exercise 11's shIrradiance in double, so with the
// reference, not with the projection a student edition keeps ------------------

dvec3 sh9Irradiance(const Sh9& coefficients, dvec3 n) {
    std::array<double, 9> Y = sh9Basis(n);
    dvec3 E(0.0);
    for (int k = 0; k < 9; ++k) E += coefficients[size_t(k)] * (sh9CosineFactor(sh9Band(k)) * Y[size_t(k)]);
    return E;
}

dvec3 environmentIrradianceSh9(const Environment& environment, const Sh9& coefficients, dvec3 worldNormal) {
    return environment.intensity * sh9Irradiance(coefficients, environmentLocalDirection(environment, worldNormal));
}

}  // namespace rl::ref
