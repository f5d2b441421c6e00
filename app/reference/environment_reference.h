// environment_reference.h: environment light in the CPU reference (issue 24,
// docs/model.md "Environment light"), in double. At a surface point it
// estimates the exact integral
//     L_env(p, v) = integral over the hemisphere of f(n, v, l) L(l) V(p, l) (n.l) dl
// (f the scene's BRDF, L the radiance map scaled and turned, V = 1 where a ray
// from p towards l leaves the scene, or V = 1 everywhere without visibility)
// by Monte Carlo with a fixed seed: per estimate, `samples` directions drawn
// from the BRDF (GGX visible normals, Heitz 2018, and a cosine lobe) and `samples` drawn from
// the radiance map (a CDF over its pixels), combined by multiple importance
// sampling with the balance heuristic (Veach 1997, ch. 9). The estimate is
// unbiased: its error falls as 1/sqrt(samples).
#pragma once

#include "core/environment_image.h"
#include "core/scene.h"
#include "reference/cpu_reference.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace rl::ref {

// How the reference integrates environment light.
struct EnvironmentOptions {
    // Directions per strategy per hit (so 2 x samples BRDF evaluations).
    // 256 at the default: on the shipped sky, a hit's standard deviation is
    // under 1% of its value for rough surfaces (docs/model.md gives figures).
    int samples = 256;
    std::uint64_t seed = 1;  // the fixed seed: the same picture every run and on every thread count
    bool visibility = true;  // V: other spheres (and a sphere's own inside) block the environment
};

// A small, fast, seedable generator (SplitMix64, Steele et al. 2014): the
// reference's only source of randomness, so its pictures are the same bits
// on every machine.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    double uniform();  // in [0, 1), 53 random bits
private:
    std::uint64_t state_;
};

// A seed from several numbers (the options' seed, a ray's bits, a bounce).
std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b);

// Importance sampling of a radiance map by the bilinear lookup's own
// distribution: a pixel is drawn with probability proportional to (its
// luminance + 1% of the mean luminance) times its solid angle, then a point
// around its centre with the weight the lookup gives the pixel there (a tent
// of one pixel each way in x and in y, wrapping in u, the half pixel beyond
// the first and last row folded back as the lookup clamps). The density is
// then the pixels' probabilities interpolated as the lookup interpolates
// their radiance, so radiance over density stays within the pixels' own
// ratios (plus the sin(theta) of the equirectangular mapping): a one-pixel sun
// is sampled where the lookup spreads it, not only at the floor. The 1% keeps
// every direction possible. Works in the image's own frame.
class EnvironmentSampler {
public:
    explicit EnvironmentSampler(const RadianceImage& image);
    struct Sample {
        glm::dvec3 direction;  // unit, in the image's frame
        double pdf;            // per steradian
    };
    Sample sample(double u1, double u2, double u3) const;
    double pdf(glm::dvec3 localDirection) const;  // per steradian, of a unit direction in the image's frame
    double pdf(glm::dvec2 uv, double cosTheta) const;  // the same from its equirectUv() and its y

private:
    int width_ = 0, height_ = 0;
    std::vector<double> cdf_;          // over the pixels, row-major from the top; cdf_.back() = 1
    std::vector<double> probability_;  // each pixel's probability
};

// The sampler of an environment's image, built once per image (cached while
// the image lives; thread-safe).
std::shared_ptr<const EnvironmentSampler> environmentSampler(const Environment& environment);

// A BRDF for integrateEnvironmentLight(): its value and how to draw from it.
struct SurfaceBrdf {
    std::function<glm::dvec3(glm::dvec3 l)> f;  // per steradian; integrateEnvironmentLight() skips n.l <= 0
    double alpha = 1.0;          // width of the GGX lobe the specular draws use
    double specularShare = 0.5;  // share of BRDF draws from GGX half vectors, the rest from the cosine lobe
};

// The MIS estimate of the integral above at a point with unit normal n, seen
// from v (unit, n.v >= 0): `samples` BRDF draws and `samples` map draws from
// `random`. `escapes(l)` is V (nullptr: V = 1).
glm::dvec3 integrateEnvironmentLight(const Environment& environment, const EnvironmentSampler& sampler,
                                     glm::dvec3 n, glm::dvec3 v, const SurfaceBrdf& brdf,
                                     const std::function<bool(glm::dvec3 l)>& escapes, int samples,
                                     Random& random);

// The scene's BRDF at a hit (cookTorranceBRDF with scene.model), with its
// sampling: GGX visible-normal draws for the specular lobe (every model variant: GGX's tail
// is the widest of them), cosine draws for the diffuse one, shared by their
// rough weight at n.v.
SurfaceBrdf sceneBrdf(const Scene& scene, const Hit& hit, glm::dvec3 v);

// Environment light the hit sends towards v (the integral above with the
// scene's BRDF), seeded from `seed` (reference: mixSeed of the options' seed
// and the ray). Zero when the scene has no environment.
glm::dvec3 environmentLight(const Scene& scene, const Hit& hit, glm::dvec3 v, const EnvironmentOptions& options,
                            std::uint64_t seed);

}  // namespace rl::ref
