// sh9.cpp: see sh9.h.
#include "reference/sh9.h"

#include "reference/brdf_reference.h"

#include <cmath>

namespace rl::ref {

using glm::dvec3;

std::array<double, 9> sh9Basis(dvec3 d) {
    const double c0 = 0.5 * std::sqrt(1.0 / kPi);         // 0.282095
    const double c1 = std::sqrt(3.0 / (4.0 * kPi));        // 0.488603
    const double c2 = std::sqrt(15.0 / (4.0 * kPi));       // 1.092548
    const double c20 = std::sqrt(5.0 / (16.0 * kPi));      // 0.315392
    const double c22 = std::sqrt(15.0 / (16.0 * kPi));     // 0.546274
    const double x = d.x, y = d.y, z = d.z;
    return {c0,          c1 * y,     c1 * z,     c1 * x, c2 * x * y,
            c2 * y * z,  c20 * (3.0 * z * z - 1.0), c2 * x * z, c22 * (x * x - y * y)};
}

int sh9Band(int k) { return k == 0 ? 0 : k < 4 ? 1 : 2; }

double sh9CosineFactor(int band) {
    switch (band) {
        case 0: return kPi;
        case 1: return 2.0 * kPi / 3.0;
        default: return kPi / 4.0;
    }
}

Sh9 projectSh9(const RadianceImage& image) {
    Sh9 out;
    out.fill(dvec3(0.0));
    const int W = image.width, H = image.height;
    for (int y = 0; y < H; ++y) {
        double cosTop = std::cos(kPi * y / H), cosBottom = std::cos(kPi * (y + 1) / H);
        if (y == 0) cosTop = 1.0;
        if (y == H - 1) cosBottom = -1.0;
        double solidAngle = 2.0 * kPi / W * (cosTop - cosBottom);
        double v = (y + 0.5) / H;
        for (int x = 0; x < W; ++x) {
            const float* p = image.at(x, y);
            dvec3 L(p[0], p[1], p[2]);
            std::array<double, 9> Y = sh9Basis(equirectDirection((x + 0.5) / W, v));
            for (int k = 0; k < 9; ++k) out[size_t(k)] += L * (Y[size_t(k)] * solidAngle);
        }
    }
    return out;
}

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
