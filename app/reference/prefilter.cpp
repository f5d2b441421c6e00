// prefilter.cpp: the environment prefiltered for the split sum (see
// split_sum.h): framework precomputation of what exercise 11 samples, no
// term of the model, so a student edition keeps it.
#include "reference/split_sum.h"

#include "core/environment_image.h"
#include "reference/brdf_reference.h"  // kMinRoughness (declarations only: a student edition keeps it)

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::ref {

using glm::dvec2;
using glm::dvec3;

namespace {

constexpr double kPiPrefilter = 3.14159265358979323846;

// Van der Corput's radical inverse in base 2: the second coordinate of Hammersley point i.
double radicalInverse(unsigned bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * (1.0 / 4294967296.0);
}

// The radiance map's pyramid for filtered importance sampling: level 0 the
// map, each next level its 2 x 2 blocks averaged by their pixels' solid
// angles (an odd side keeps its last column or row alone), down to one row.
std::vector<RadianceImage> pyramidOf(const RadianceImage& image) {
    std::vector<RadianceImage> levels{image};
    while (levels.back().width > 1 && levels.back().height > 1) levels.push_back(halvedBySolidAngle(levels.back()));
    return levels;
}

// The pyramid's radiance towards uv at a fractional level (bilinear in each,
// linear between the two).
dvec3 pyramidRadiance(const std::vector<RadianceImage>& pyramid, glm::dvec2 uv, double level) {
    const double l = std::clamp(level, 0.0, double(pyramid.size() - 1));
    const int k0 = int(std::floor(l));
    const int k1 = std::min(k0 + 1, int(pyramid.size()) - 1);
    const dvec3 a = bilinearRadiance(pyramid[size_t(k0)], uv.x, uv.y);
    if (k1 == k0) return a;
    return a + (bilinearRadiance(pyramid[size_t(k1)], uv.x, uv.y) - a) * (l - k0);
}

RadianceImage prefilterFromPyramid(const std::vector<RadianceImage>& pyramid, double roughness, int width, int height,
                                   int samples);

}  // namespace

// A GGX half vector around +z for (u1, u2): n.h from Walter et al. 2007 eq. 35.
dvec3 ggxHalfVector(double u1, double u2, double alpha) {
    double a2 = alpha * alpha;
    double cos2 = (1.0 - u1) / (1.0 + (a2 - 1.0) * u1);
    double cosTheta = std::sqrt(std::max(0.0, cos2));
    double sinTheta = std::sqrt(std::max(0.0, 1.0 - cos2));
    double phi = 2.0 * kPiPrefilter * u2;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

RadianceImage prefilterEnvironment(const RadianceImage& image, double roughness, int width, int height, int samples) {
    return prefilterFromPyramid(pyramidOf(image), roughness, width, height, samples);
}

namespace {

RadianceImage prefilterFromPyramid(const std::vector<RadianceImage>& pyramid, double roughness, int width, int height,
                                   int samples) {
    const RadianceImage& image = pyramid.front();
    // alpha = r^2, r = clamp(roughness, kMinRoughness, 1): the framework's
    // roughness convention (docs/model.md), stated in exercise 08's stub.
    const double r = std::clamp(roughness, kMinRoughness, 1.0), alpha = r * r;
    const int N = std::max(samples, 1);
    // The Hammersley half vectors around +z, the same for every pixel.
    std::vector<dvec3> halfVectors(size_t(N), dvec3(0.0));
    std::vector<double> sampleSolidAngle(size_t(N), 0.0);
    for (int i = 0; i < N; ++i) {
        halfVectors[size_t(i)] = ggxHalfVector((i + 0.5) / N, radicalInverse(unsigned(i)), alpha);
        // Filtered importance sampling (Krivanek and Colbert 2008): each draw
        // stands for the solid angle 1 / (N pdf(l)), pdf(l) = D(h) / 4 with
        // n = v = r, and reads the pyramid level whose pixel is that large,
        // so a small bright source is spread over the draws' footprints
        // instead of caught by a few of them.
        const double NoH = halfVectors[size_t(i)].z, a2 = alpha * alpha;
        const double d = NoH * NoH * (a2 - 1.0) + 1.0;
        const double D = a2 / (kPiPrefilter * d * d);
        // The sharpest level (roughness 0) reads the map itself: its lobe is
        // narrower than a pixel, and its few draws in GGX's long tail would
        // otherwise spread a sun over degrees around it.
        sampleSolidAngle[size_t(i)] = roughness <= 0.0 ? 0.0 : 4.0 / (N * D);
    }
    const double pixelSolidAngle = 2.0 * kPiPrefilter * kPiPrefilter / (double(image.width) * double(image.height));
    RadianceImage out;
    out.width = width;
    out.height = height;
    out.rgb.assign(size_t(width) * size_t(height) * 3, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            dvec3 r = equirectDirection((x + 0.5) / width, (y + 0.5) / height);
            // Tangent frame around r (Duff et al. 2017).
            double sign = std::copysign(1.0, r.z);
            double a = -1.0 / (sign + r.z);
            double c = r.x * r.y * a;
            dvec3 t(1.0 + sign * r.x * r.x * a, sign * c, -sign * r.x);
            dvec3 b(c, sign + r.y * r.y * a, -r.y);
            dvec3 sum(0.0);
            double weight = 0.0;
            for (const dvec3& hl : halfVectors) {
                dvec3 h = hl.x * t + hl.y * b + hl.z * r;
                double VoH = glm::dot(r, h);  // v = n = r
                dvec3 l = 2.0 * VoH * h - r;
                double NoL = glm::dot(r, l);
                if (NoL <= 0.0) continue;
                l = glm::normalize(l);
                glm::dvec2 uv = equirectUv(l);
                const double sinTheta = std::sqrt(std::max(1e-6, 1.0 - l.y * l.y));
                const double share = sampleSolidAngle[size_t(&hl - halfVectors.data())];
                // The level whose pixel is the draw's footprint, with no bias:
                // Krivanek and Colbert's +1 (a smoother chain) spread the soft
                // boxes' light into the sharp levels' tails (a dark panel of the
                // studio's chrome ball 8% over the reference); the sun, which it
                // kept whole, is a light of its own and not in this map
                // (docs/decisions.md).
                const double level = share > 0.0 ? 0.5 * std::log2(share / (pixelSolidAngle * sinTheta)) : 0.0;
                sum += pyramidRadiance(pyramid, uv, level) * NoL;
                weight += NoL;
            }
            dvec3 value = weight > 0.0 ? sum / weight : dvec3(0.0);
            float* p = out.at(x, y);
            for (int k = 0; k < 3; ++k) p[k] = float(value[k]);
        }
    return out;
}

}  // namespace

double prefilterLevelRoughness(int level, int levels) { return levels > 1 ? double(level) / (levels - 1) : 0.0; }

int prefilterLevelWidth(double roughness, int width) {
    const double r = std::clamp(roughness, kMinRoughness, 1.0), alpha = r * r;
    int w = 8;
    while (w < width && w * alpha < kPiPrefilter) w *= 2;
    return std::min(w, std::max(width, 8));
}

std::vector<RadianceImage> prefilterChain(const RadianceImage& image, int width, int height, int levels, int samples) {
    std::vector<RadianceImage> chain;
    const std::vector<RadianceImage> pyramid = pyramidOf(image);
    for (int k = 0; k < levels; ++k) {
        const int w = prefilterLevelWidth(prefilterLevelRoughness(k, levels), width);
        const int h = std::max(int(std::lround(double(w) * height / std::max(width, 1))), 4);
        chain.push_back(prefilterFromPyramid(pyramid, prefilterLevelRoughness(k, levels), w, h, samples));
    }
    return chain;
}

}  // namespace rl::ref
