// sh9.cpp: see sh9.h.
#include "reference/sh9.h"

#include "reference/brdf_reference.h"

#include <algorithm>
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

namespace {

// Antiderivatives in mu = cos(theta) = y and in phi, for the exact integrals
// of the basis over one pixel (x = s sin(phi), z = -s cos(phi), s = sqrt(1 - mu^2)).
double sqrtOneMinus(double mu) { return std::sqrt(std::max(0.0, 1.0 - mu * mu)); }
double intS(double mu) { return 0.5 * (mu * sqrtOneMinus(mu) + std::asin(std::clamp(mu, -1.0, 1.0))); }  // s
double intMuS(double mu) { double s = sqrtOneMinus(mu); return -s * s * s / 3.0; }                      // mu s
double intOneMinusMu2(double mu) { return mu - mu * mu * mu / 3.0; }                                     // 1 - mu^2
double intMu2(double mu) { return mu * mu * mu / 3.0; }                                                  // mu^2

// The integral of each basis function over the pixel phi in [p0, p1], mu in [m1, m0] (m1 < m0).
std::array<double, 9> basisIntegrals(double p0, double p1, double m0, double m1) {
    const double c0 = 0.5 * std::sqrt(1.0 / kPi);
    const double c1 = std::sqrt(3.0 / (4.0 * kPi));
    const double c2 = std::sqrt(15.0 / (4.0 * kPi));
    const double c20 = std::sqrt(5.0 / (16.0 * kPi));
    const double c22 = std::sqrt(15.0 / (16.0 * kPi));
    auto between = [&](double (*f)(double)) { return f(m0) - f(m1); };
    double dPhi = p1 - p0;
    double dMu = m0 - m1;
    double sinI = -std::cos(p1) + std::cos(p0);                                  // of sin(phi)
    double cosI = std::sin(p1) - std::sin(p0);                                   // of cos(phi)
    double sin2I = (dPhi - 0.5 * (std::sin(2 * p1) - std::sin(2 * p0))) / 2.0;    // of sin^2(phi)
    double cos2I = dPhi - sin2I;                                                 // of cos^2(phi)
    double sinCosI = 0.5 * (std::sin(p1) * std::sin(p1) - std::sin(p0) * std::sin(p0));  // of sin cos
    double S = between(intS), MuS = between(intMuS), OneMinus = between(intOneMinusMu2), Mu2 = between(intMu2);
    double Mu = 0.5 * (m0 * m0 - m1 * m1);
    double x = S * sinI, y = Mu * dPhi, z = -S * cosI;
    double xy = MuS * sinI, yz = -MuS * cosI, xz = -OneMinus * sinCosI;
    double zz = OneMinus * cos2I, xx = OneMinus * sin2I, yy = Mu2 * dPhi;
    return {c0 * dPhi * dMu, c1 * y, c1 * z, c1 * x, c2 * xy, c2 * yz, c20 * (3.0 * zz - dPhi * dMu), c2 * xz,
            c22 * (xx - yy)};
}

}  // namespace

Sh9 projectSh9(const RadianceImage& image) {
    Sh9 out;
    out.fill(dvec3(0.0));
    const int W = image.width, H = image.height;
    for (int y = 0; y < H; ++y) {
        double cosTop = y == 0 ? 1.0 : std::cos(kPi * y / H);
        double cosBottom = y == H - 1 ? -1.0 : std::cos(kPi * (y + 1) / H);
        for (int x = 0; x < W; ++x) {
            // Pixel x spans u in [x/W, (x+1)/W), phi = 2 pi (u - 1/2).
            double p0 = 2.0 * kPi * (double(x) / W - 0.5), p1 = 2.0 * kPi * (double(x + 1) / W - 0.5);
            std::array<double, 9> I = basisIntegrals(p0, p1, cosTop, cosBottom);
            const float* p = image.at(x, y);
            dvec3 L(p[0], p[1], p[2]);
            for (int k = 0; k < 9; ++k) out[size_t(k)] += L * I[size_t(k)];
        }
    }
    return out;
}

}  // namespace rl::ref
