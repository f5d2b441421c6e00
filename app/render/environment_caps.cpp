// environment_caps.cpp: the radiance map averaged over caps; see environment_caps.h.
#include "render/environment_caps.h"

#include "core/environment_image.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxWidth = 256;

// A map with its pixels' directions and solid angles, in double.
struct Source {
    int width = 0, height = 0;
    std::vector<glm::dvec3> radiance;  // per pixel
    std::vector<double> solidAngle;    // per row
    std::vector<glm::dvec3> direction; // per pixel, the centre's
};

// The image, halved (halvedBySolidAngle) until it is at most kMaxWidth wide.
Source downsampled(const RadianceImage& image) {
    RadianceImage halved;
    const RadianceImage* small = &image;
    for (; small->width > kMaxWidth; small = &halved) halved = halvedBySolidAngle(*small);
    const int w = small->width, h = small->height;
    std::vector<glm::dvec3> L(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = small->at(x, y);
            L[std::size_t(y) * w + x] = glm::dvec3(p[0], p[1], p[2]);
        }
    Source s;
    s.width = w;
    s.height = h;
    s.radiance = std::move(L);
    for (int y = 0; y < h; ++y) s.solidAngle.push_back(equirectPixelSolidAngle(y, w, h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) s.direction.push_back(equirectDirection((x + 0.5) / w, (y + 0.5) / h));
    return s;
}

int levelWidth(double cap, int imageWidth) {
    const double ideal = 8.0 * kPi / cap;
    int width = 8;
    while (width < kMaxWidth && width * 1.5 < ideal) width *= 2;
    return std::max(2, std::min(width, std::min(imageWidth - imageWidth % 2, kMaxWidth)));
}

// The mean over the cap of half-angle `cap` around the direction at polar
// angle theta (0 straight up) and u's angle phi: sum(w_p L_p dOmega_p) /
// sum(w_p dOmega_p), w_p the pixel's share inside the antialiased edge.
glm::dvec3 capMean(const Source& s, double cap, double theta, double phi) {
    const double pixel = kPi / s.height;
    const double reach = cap + pixel;  // beyond this no pixel has weight
    const double cosReach = std::cos(std::min(reach, kPi));
    const double cosOuter = std::cos(std::min(cap + 0.5 * pixel, kPi));  // weight 0 at or beyond
    const double cosInner = std::cos(std::max(cap - 0.5 * pixel, 0.0));  // weight 1 at or within
    const glm::dvec3 w = equirectDirection(phi / (2.0 * kPi), theta / kPi);
    const int y0 = std::max(0, int(std::floor((theta - reach) / pixel)));
    const int y1 = std::min(s.height - 1, int(std::ceil((theta + reach) / pixel)));
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (int y = y0; y <= y1; ++y) {
        // The columns the cap can reach in this row: all where it holds a pole.
        const double sinRow = std::min(std::sin(kPi * y / s.height), std::sin(kPi * (y + 1) / s.height));
        int first = 0, count = s.width;
        if (theta - reach > 0.0 && theta + reach < kPi && sinRow > std::sin(reach)) {
            const double dphi = std::asin(std::sin(reach) / sinRow);
            const int half = int(std::ceil(dphi / (2.0 * kPi) * s.width)) + 1;
            if (2 * half + 1 < s.width) {
                first = int(std::floor(phi / (2.0 * kPi) * s.width)) - half;
                count = 2 * half + 1;
            }
        }
        for (int i = 0; i < count; ++i) {
            const int x = ((first + i) % s.width + s.width) % s.width;
            const std::size_t k = std::size_t(y) * s.width + x;
            const double c = glm::dot(s.direction[k], w);
            if (c < cosReach || c <= cosOuter) continue;
            const double inside =
                c >= cosInner ? 1.0 : std::clamp(0.5 + (cap - std::acos(std::clamp(c, -1.0, 1.0))) / pixel, 0.0, 1.0);
            sum += inside * s.solidAngle[std::size_t(y)] * s.radiance[k];
            weight += inside * s.solidAngle[std::size_t(y)];
        }
    }
    return weight > 0.0 ? sum / weight : glm::dvec3(0.0);
}

CapLevel capLevel(const Source& s, double cap, int width) {
    CapLevel level;
    RadianceImage& out = level.means;
    out.width = width;
    out.height = std::max(1, width / 2);
    out.rgb.assign(std::size_t(out.width) * out.height * 3, 0.0f);
    for (int ty = 0; ty < out.height; ++ty)
        for (int tx = 0; tx < out.width; ++tx) {
            // u's angle: a column's is 2 pi (x + 1/2) / W.
            const glm::dvec3 mean = capMean(s, cap, kPi * (ty + 0.5) / out.height, 2.0 * kPi * (tx + 0.5) / out.width);
            float* p = out.at(tx, ty);
            for (int c = 0; c < 3; ++c) p[c] = float(mean[c]);
        }
    level.north = capMean(s, cap, 0.0, 0.0);
    level.south = capMean(s, cap, kPi, 0.0);
    return level;
}

}  // namespace

double capLevelAngle(int level) { return kSmallestCap * std::pow(2.0, 0.5 * level); }

namespace {
double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }
}  // namespace

EnvironmentSun findSun(const RadianceImage& image) {
    EnvironmentSun sun;
    const int W = image.width, H = image.height;
    int brightest = 0;
    double mean = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double l = luminance(image.at(x, y));
            mean += l * equirectPixelSolidAngle(y, W, H);
            if (l > luminance(&image.rgb[3 * std::size_t(brightest)])) brightest = y * W + x;
        }
    mean /= 4.0 * kPi;
    const double peak = luminance(&image.rgb[3 * std::size_t(brightest)]);
    if (!(peak > 0.0)) return sun;
    const glm::dvec3 centre = equirectDirection((brightest % W + 0.5) / W, (brightest / W + 0.5) / H);
    const double cosReach = std::cos(kSunReach), cosAround = std::cos(2.0 * kSunReach);
    bool isolated = true;
    glm::dvec3 weighted(0.0);
    double solidAngle = 0.0, lumPower = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 d = equirectDirection((x + 0.5) / W, (y + 0.5) / H);
            const float* p = image.at(x, y);
            if (luminance(p) < kSunFloor * peak) continue;
            if (glm::dot(d, centre) < cosReach) {
                isolated = isolated && glm::dot(d, centre) < cosAround;  // a bright pixel just beyond: a wide source
                continue;
            }
            const double omega = equirectPixelSolidAngle(y, W, H);
            sun.pixels.push_back(y * W + x);
            sun.power += omega * glm::dvec3(p[0], p[1], p[2]);
            weighted += omega * luminance(p) * d;
            lumPower += omega * luminance(p);
            solidAngle += omega;
        }
    if (!isolated || solidAngle > kSunSolidAngle || lumPower / solidAngle < kSunContrast * mean || glm::length(weighted) == 0.0) {
        sun = EnvironmentSun{};
        return sun;
    }
    // The sky around it: the mean of the other pixels within twice its reach;
    // its power is what it brings above that.
    std::vector<char> isSun(std::size_t(W) * H, 0);
    for (int k : sun.pixels) isSun[std::size_t(k)] = 1;
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (isSun[std::size_t(y) * W + x]) continue;
            if (glm::dot(equirectDirection((x + 0.5) / W, (y + 0.5) / H), centre) < cosAround) continue;
            const float* p = image.at(x, y);
            const double omega = equirectPixelSolidAngle(y, W, H);
            sum += omega * glm::dvec3(p[0], p[1], p[2]);
            weight += omega;
        }
    sun.around = weight > 0.0 ? sum / weight : glm::dvec3(0.0);
    sun.power = glm::max(sun.power - solidAngle * sun.around, glm::dvec3(0.0));
    sun.present = true;
    sun.direction = glm::normalize(weighted);
    sun.angularRadius = std::acos(1.0 - solidAngle / (2.0 * kPi));
    return sun;
}

RadianceImage mapWithoutSun(const RadianceImage& image, const EnvironmentSun& sun) {
    RadianceImage out = image;
    for (int k : sun.pixels)
        for (int c = 0; c < 3; ++c) out.rgb[3 * std::size_t(k) + std::size_t(c)] = float(sun.around[c]);
    return out;
}

glm::dvec3 capLevelLookup(const CapLevel& level, double u, double v) {
    const RadianceImage& m = level.means;
    const double y = v * m.height - 0.5;
    // Between a pole and the first or last row's centres: towards the pole's
    // own mean, linearly in the polar angle (every lookup holds a cap's mean,
    // the clamped row's would be the cap half a row away from the pole).
    if (y < 0.0) return glm::mix(level.north, bilinearRadiance(m, u, 0.5 / m.height), std::max(0.0, 2.0 * y + 1.0));
    if (y > m.height - 1.0)
        return glm::mix(level.south, bilinearRadiance(m, u, 1.0 - 0.5 / m.height), std::max(0.0, 2.0 * (m.height - 0.5 - y)));
    return bilinearRadiance(m, u, v);
}

std::vector<CapLevel> capAverageChain(const RadianceImage& image) {
    const Source s = downsampled(image);
    std::vector<CapLevel> chain;
    for (int k = 0; k < kCapLevels; ++k) {
        const double cap = capLevelAngle(k);
        chain.push_back(capLevel(s, cap, levelWidth(cap, s.width)));
    }
    return chain;
}

}  // namespace rl
