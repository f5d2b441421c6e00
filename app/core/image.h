// Images that cross module boundaries: linear radiance (float RGB) and the
// display-encoded 8-bit picture. Both are stored with row 0 at the TOP, as
// PNG stores them; PFM output flips to its bottom-to-top order on write.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rl {

struct RadianceImage {  // linear radiance, before exposure and tone mapping
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3 floats per pixel
    float* at(int x, int yFromTop) { return &rgb[3 * (size_t(yFromTop) * width + x)]; }
    const float* at(int x, int yFromTop) const { return &rgb[3 * (size_t(yFromTop) * width + x)]; }
};

struct DisplayImage {  // 8-bit RGB after the display step
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;
    std::uint8_t* at(int x, int yFromTop) { return &rgb[3 * (size_t(yFromTop) * width + x)]; }
    const std::uint8_t* at(int x, int yFromTop) const { return &rgb[3 * (size_t(yFromTop) * width + x)]; }
};

struct Rendering {  // what every renderer (GL or CPU) produces
    RadianceImage radiance;
    DisplayImage display;
};

// Writers throw rl::Error naming the path when the file cannot be written,
// readers when it cannot be read or is not a valid file of its kind
// ("path: cannot write PNG (reason)"). PFM is written little endian; both
// byte orders and greyscale "Pf" files are read.
void writePng(const std::string& path, const DisplayImage& image);
void writePfm(const std::string& path, const RadianceImage& image);

// "" when every value of `image` is finite; otherwise "the picture holds N
// NaN or Inf values, the first at pixel (x, y)" (x from the left, y from the top).
std::string nonFiniteProblem(const RadianceImage& image);
DisplayImage readPng(const std::string& path);
RadianceImage readPfm(const std::string& path);

// 8-bit quantisation of the spec's display step: round(255 c), c clamped to
// [0, 1], halves rounded up; NaN gives 0.
std::uint8_t quantize8(double c);

// Agreement between two renders of the same size (the budgets).
// Different sizes throw rl::Error. The radiance metrics need radiance in both
// renderings (else they stay 0) and skip non-finite values, which nonFinite counts.
struct ImageDiff {
    double offFraction = 0;     // share of pixels off by more than 1/255 in any channel
    double meanLsb = 0;         // mean absolute difference over all channels, in 8-bit units
    double p99Lsb = 0;          // 99th percentile of the per-pixel max channel difference
    int maxLsb = 0;
    double pfmMedianRel = 0;    // median over channels of |a-b| / (|b| + 1e-3) of the radiance (PFM)
    double relMse = 0;          // mean of (a-b)^2 / (b^2 + 1e-2) over channels
    double psnr = 0;            // of the 8-bit pictures, dB (inf when identical)
    long nonFinite = 0;         // NaN or Inf channels in either radiance image
};
ImageDiff compareRenderings(const Rendering& got, const Rendering& expected);

// A heat map of the per-pixel max channel difference (black = equal,
// yellow-red = off by 8+ LSB), for check and grading reports.
DisplayImage differenceHeatMap(const DisplayImage& got, const DisplayImage& expected);

}  // namespace rl
