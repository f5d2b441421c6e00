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
    const size_t count = size_t(width_) * size_t(height_);
    // Each pixel's weight: (its luminance + the floor) times its solid angle.
    std::vector<double> solidAngle(static_cast<size_t>(height_));
    for (int y = 0; y < height_; ++y)
        solidAngle[size_t(y)] = equirectPixelSolidAngle(y, width_, height_);
    double mean = 0.0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) mean += luminance(image.at(x, y)) * solidAngle[size_t(y)];
    mean /= 4.0 * pi;
    // Black image: uniform over the sphere.
    const double floor = mean > 0.0 ? 0.01 * mean : 1.0;
    cdf_.resize(count);
    probability_.resize(count);
    double total = 0.0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t k = size_t(y) * width_ + x;
            probability_[k] = (luminance(image.at(x, y)) + floor) * solidAngle[size_t(y)];
            total += probability_[k];
            cdf_[k] = total;
        }
    for (size_t k = 0; k < count; ++k) {
        cdf_[k] /= total;
        probability_[k] /= total;
    }
    cdf_.back() = 1.0;
}

namespace {
// A tent on [-1, 1] (the sum of two uniforms, minus 1): the weight a pixel's
// value has in the bilinear lookup at that offset from its centre, in pixels.
double tent(double u1, double u2) { return u1 + u2 - 1.0; }
}  // namespace

EnvironmentSampler::Sample EnvironmentSampler::sample(double u1, double u2, double u3) const {
    size_t k = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u1) - cdf_.begin());
    k = std::min(k, cdf_.size() - 1);
    const int px = int(k % size_t(width_));
    const int py = int(k / size_t(width_));
    // Where the bilinear lookup spreads the pixel: a tent around its centre in
    // each axis (texel coordinates x = u W - 1/2, y = v H - 1/2). Two more
    // uniforms per axis from the two given ones (their low and high bits).
    auto split = [](double u, double& a, double& b) {
        const double scaled = u * 4294967296.0;
        a = std::floor(scaled) / 4294967296.0;
        b = scaled - std::floor(scaled);
    };
    double a2, b2, a3, b3;
    split(u2, a2, b2);
    split(u3, a3, b3);
    double x = px + tent(a2, b2);
    double y = py + tent(a3, b3);
    // The lookup clamps y to the first and last centre: the half pixel beyond
    // each is folded back, so the density there is the edge row's alone.
    if (y < -0.5) y = -1.0 - y;
    if (y > height_ - 0.5) y = 2.0 * height_ - 1.0 - y;
    const double u = (x + 0.5) / width_;  // wraps: atan2 does
    const double v = std::clamp((y + 0.5) / height_, 0.0, 1.0);
    const double theta = kPi * v;
    const double phi = (u - 0.5) * 2.0 * kPi;
    Sample s;
    s.direction = dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
    s.pdf = pdf(glm::dvec2(u - std::floor(u), v), std::cos(theta));
    return s;
}

double EnvironmentSampler::pdf(dvec3 d) const { return pdf(equirectUv(d), d.y); }

double EnvironmentSampler::pdf(glm::dvec2 uv, double cosTheta) const {
    // The pixels' probabilities interpolated exactly as the lookup
    // interpolates their radiance (bilinearRadiance: between centres,
    // wrapping in u, clamped in v): the density per unit of texel area.
    const double x = uv.x * width_ - 0.5;
    const double y = std::clamp(uv.y * height_ - 0.5, 0.0, double(height_ - 1));
    const double fx = std::floor(x), fy = std::floor(y);
    int x0 = int(fx) % width_;
    if (x0 < 0) x0 += width_;
    const int x1 = x0 + 1 >= width_ ? 0 : x0 + 1;
    const int y0 = int(fy);
    const int y1 = std::min(y0 + 1, height_ - 1);
    const double ax = x - fx, ay = y - fy;
    auto p = [&](int px, int py) { return probability_[size_t(py) * width_ + px]; };
    const double perTexel = (1 - ay) * ((1 - ax) * p(x0, y0) + ax * p(x1, y0)) + ay * ((1 - ax) * p(x0, y1) + ax * p(x1, y1));
    // Per steradian: d(omega) = sin(theta) d(theta) d(phi) = 2 pi^2 sin(theta) du dv, and du dv = dx dy / (W H).
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double jacobian = 2.0 * kPi * kPi * std::max(sinTheta, 1e-12) / (double(width_) * double(height_));
    return perTexel / jacobian;
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
