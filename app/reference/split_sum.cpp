// split_sum.cpp: see split_sum.h.
#include "reference/split_sum.h"

#include "core/environment_image.h"
#include "reference/brdf_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::ref {

using glm::dvec2;
using glm::dvec3;

namespace {

// A GGX half vector around +z for (u1, u2): n.h from Walter et al. 2007 eq. 35.
dvec3 ggxHalfVector(double u1, double u2, double alpha) {
    double a2 = alpha * alpha;
    double cos2 = (1.0 - u1) / (1.0 + (a2 - 1.0) * u1);
    double cosTheta = std::sqrt(std::max(0.0, cos2));
    double sinTheta = std::sqrt(std::max(0.0, 1.0 - cos2));
    double phi = 2.0 * kPi * u2;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Van der Corput's radical inverse in base 2: the second coordinate of Hammersley point i.
double radicalInverse(unsigned bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * (1.0 / 4294967296.0);
}

}  // namespace

dvec2 splitSumBrdf(double NoV, double roughness, int samples) {
    NoV = std::clamp(NoV, kMinNoV, 1.0);
    const double alpha = ggxAlpha(roughness);
    const dvec3 v(std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), 0.0, NoV);
    const int N = std::max(samples, 1);
    dvec2 sum(0.0);
    for (int a = 0; a < N; ++a)
        for (int b = 0; b < N; ++b) {
            dvec3 h = ggxHalfVector((a + 0.5) / N, (b + 0.5) / N, alpha);
            double VoH = glm::dot(v, h);
            if (VoH <= 0.0) continue;
            double NoL = 2.0 * VoH * h.z - v.z;  // (reflect(-v, h)).z
            if (NoL <= 0.0) continue;
            double NoH = h.z;
            double G = G_SchlickGGX(NoV, std::min(NoL, 1.0), roughness);
            double weight = G * VoH / (NoV * NoH);
            double Fc = std::pow(1.0 - VoH, 5.0);
            sum += dvec2((1.0 - Fc) * weight, Fc * weight);
        }
    return sum / double(N * N);
}

std::vector<dvec2> splitSumTable(int size, int samples) {
    std::vector<dvec2> table(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i)
            table[size_t(j) * size + i] = splitSumBrdf((i + 0.5) / size, (j + 0.5) / size, samples);
    return table;
}

RadianceImage prefilterEnvironment(const RadianceImage& image, double roughness, int width, int height, int samples) {
    const double alpha = ggxAlpha(roughness);
    const int N = std::max(samples, 1);
    // The Hammersley half vectors around +z, the same for every pixel.
    std::vector<dvec3> halfVectors(size_t(N), dvec3(0.0));
    for (int i = 0; i < N; ++i) halfVectors[size_t(i)] = ggxHalfVector((i + 0.5) / N, radicalInverse(unsigned(i)), alpha);
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
                glm::dvec2 uv = equirectUv(glm::normalize(l));
                sum += bilinearRadiance(image, uv.x, uv.y) * NoL;
                weight += NoL;
            }
            dvec3 value = weight > 0.0 ? sum / weight : dvec3(0.0);
            float* p = out.at(x, y);
            for (int k = 0; k < 3; ++k) p[k] = float(value[k]);
        }
    return out;
}

double prefilterLevelRoughness(int level, int levels) { return levels > 1 ? double(level) / (levels - 1) : 0.0; }

std::vector<RadianceImage> prefilterChain(const RadianceImage& image, int width, int height, int levels, int samples) {
    std::vector<RadianceImage> chain;
    for (int k = 0; k < levels; ++k) {
        int w = std::max(width >> k, 8), h = std::max(height >> k, 4);
        chain.push_back(prefilterEnvironment(image, prefilterLevelRoughness(k, levels), w, h, samples));
    }
    return chain;
}

}  // namespace rl::ref
