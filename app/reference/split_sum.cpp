// split_sum.cpp: see split_sum.h. The table integrates the reference's
// specular lobe, so a student edition leaves this file out and reads the
// table its instructor's build recorded (reference/absent.cpp).
#include "reference/split_sum.h"

#include "core/environment_image.h"
#include "reference/brdf_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl::ref {

using glm::dvec2;
using glm::dvec3;


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

}  // namespace rl::ref
