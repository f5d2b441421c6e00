// PNG and PFM files, the 8-bit quantisation of the display step, and the
// comparison of two renderings (see image.h for the contracts).
#include "core/image.h"

#include "core/error.h"
#include "core/file_io.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <locale>
#include <sstream>

// stb is third-party code compiled into this one file. Its functions are made
// static (private to this file) so they cannot clash with Debian's libstb or
// another copy, and stb does no file I/O of its own: we read and write the
// files here so that an error can say why (strerror) instead of stb's "can't
// fopen". stb_image only decodes PNG: that is all raylab reads.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_FAILURE_USERMSG  // "corrupt PNG" rather than stb's terse codes
// Our warning flags are for our code; stb does not build clean under -Wextra
// and its unused static functions would warn too.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wtype-limits"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace rl {

namespace {

using Bytes = std::vector<unsigned char>;

// Reads a whole regular file (core/file_io.h); throws "path: cannot read <what> (reason)".
Bytes readFile(const std::string& path, const char* what) {
    std::string data = readRegularFile(path, kMaxImageFileBytes, what);
    return Bytes(data.begin(), data.end());
}

// Writes a whole file atomically (core/file_io.h): on failure the old file is
// intact and nothing half-written is left. Throws "path: cannot write <what> (reason)".
void writeFile(const std::string& path, const char* what, const Bytes& data) {
    writeFileAtomic(path, std::string_view(reinterpret_cast<const char*>(data.data()), data.size()), WriteOptions{what});
}

// Checks that the pixel buffer matches the size; returns "" or the reason.
template <typename Image>
std::string shapeProblem(const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        return "image is empty (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")";
    std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 3;
    if (image.rgb.size() != expected)
        return "pixel buffer holds " + std::to_string(image.rgb.size()) + " values, " +
               std::to_string(image.width) + "x" + std::to_string(image.height) + " RGB needs " +
               std::to_string(expected);
    return "";
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// PFM stores IEEE-754 binary32; the byte order is explicit (scale < 0: little
// endian), so we assemble bytes ourselves instead of trusting the host's order.
static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4, "PFM needs IEEE-754 binary32 floats");

void appendFloatLE(Bytes& out, float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<unsigned char>(bits >> (8 * k)));
}

float loadFloat(const unsigned char* p, bool littleEndian) {
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k) bits |= std::uint32_t(p[littleEndian ? k : 3 - k]) << (8 * k);
    float value;
    std::memcpy(&value, &bits, 4);
    return value;
}

}  // namespace

// ---- PNG -------------------------------------------------------------------

void writePng(const std::string& path, const DisplayImage& image) {
    std::string problem = shapeProblem(image);
    if (!problem.empty()) throw Error(path + ": cannot write PNG (" + problem + ")");
    Bytes encoded;
    auto append = [](void* context, void* data, int size) {
        auto* bytes = static_cast<unsigned char*>(data);
        static_cast<Bytes*>(context)->insert(static_cast<Bytes*>(context)->end(), bytes, bytes + size);
    };
    // stb writes rows in the order given, first row on top, as image.h stores them.
    if (!stbi_write_png_to_func(append, &encoded, image.width, image.height, 3, image.rgb.data(), image.width * 3))
        throw Error(path + ": cannot write PNG (encoding failed)");
    writeFile(path, "PNG", encoded);
}

DisplayImage readPng(const std::string& path) {
    Bytes file = readFile(path, "PNG");
    if (file.size() > std::size_t(std::numeric_limits<int>::max()))
        throw Error(path + ": cannot read PNG (file too large)");
    int w = 0, h = 0, channelsInFile = 0;
    // Ask for 3 channels: stb drops alpha, expands grey and palettes, and
    // reduces 16-bit samples to 8 bits.
    stbi_uc* pixels = stbi_load_from_memory(file.data(), int(file.size()), &w, &h, &channelsInFile, 3);
    if (!pixels) throw Error(path + ": cannot read PNG (" + stbi_failure_reason() + ")");
    DisplayImage image;
    image.width = w;
    image.height = h;
    image.rgb.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 3);
    stbi_image_free(pixels);
    return image;
}

// ---- PFM -------------------------------------------------------------------
// "PF\n<width> <height>\n<scale>\n" then width*height RGB binary32 triples,
// rows from the BOTTOM of the image to the top; scale < 0 means little endian.

void writePfm(const std::string& path, const RadianceImage& image) {
    std::string problem = shapeProblem(image);
    if (!problem.empty()) throw Error(path + ": cannot write PFM (" + problem + ")");
    std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    Bytes out(header.begin(), header.end());
    out.reserve(header.size() + image.rgb.size() * 4);
    for (int row = image.height - 1; row >= 0; --row) {  // bottom row first
        const float* p = image.at(0, row);
        for (int k = 0; k < image.width * 3; ++k) appendFloatLE(out, p[k]);
    }
    writeFile(path, "PFM", out);
}

std::string nonFiniteProblem(const RadianceImage& image) {
    long bad = 0;
    std::size_t first = 0;
    for (std::size_t k = 0; k < image.rgb.size(); ++k)
        if (!std::isfinite(image.rgb[k]) && bad++ == 0) first = k / 3;
    if (bad == 0) return "";
    std::size_t width = std::size_t(std::max(image.width, 1));
    return "the picture holds " + std::to_string(bad) + " NaN or Inf values, the first at pixel (" +
           std::to_string(first % width) + ", " + std::to_string(first / width) + ")";
}

RadianceImage readPfm(const std::string& path) {
    Bytes file = readFile(path, "PFM");
    auto fail = [&](const std::string& reason) { return Error(path + ": cannot read PFM (" + reason + ")"); };

    // Header: four whitespace-separated tokens, the last followed by exactly
    // one whitespace character before the binary data.
    std::size_t pos = 0;
    auto isSpace = [](unsigned char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
    auto token = [&]() {
        while (pos < file.size() && isSpace(file[pos])) ++pos;
        std::size_t start = pos;
        while (pos < file.size() && !isSpace(file[pos]) && pos - start < 32) ++pos;  // 32: longer than any valid token
        return std::string(file.begin() + std::ptrdiff_t(start), file.begin() + std::ptrdiff_t(pos));
    };
    std::string magic = token();
    int channels = magic == "PF" ? 3 : magic == "Pf" ? 1 : 0;
    if (channels == 0) throw fail("not a PFM file: it starts with \"" + magic.substr(0, 8) + "\", not \"PF\"");
    auto positiveInt = [&](const std::string& text, const char* name) {
        char* end = nullptr;
        errno = 0;
        long v = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno != 0 || v <= 0 || v > std::numeric_limits<int>::max())
            throw fail(std::string("bad ") + name + " \"" + text + "\"");
        return int(v);
    };
    int width = positiveInt(token(), "width");
    int height = positiveInt(token(), "height");
    std::string scaleText = token();
    std::istringstream scaleStream(scaleText);
    scaleStream.imbue(std::locale::classic());  // "-1.0" whatever the user's decimal comma
    double scale = 0.0;
    scaleStream >> scale;
    if (scaleStream.fail() || scaleStream.peek() != EOF || !std::isfinite(scale) || scale == 0.0)
        throw fail("bad scale \"" + scaleText + "\"");
    bool littleEndian = scale < 0;  // |scale| is a unit hint that raylab does not use
    if (pos >= file.size() || !isSpace(file[pos])) throw fail("no whitespace between header and pixels");
    ++pos;

    std::uint64_t values = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(channels);
    std::uint64_t available = file.size() - pos;
    if (available != values * 4)  // checked before allocating: a lying header cannot ask for gigabytes
        throw fail("expected " + std::to_string(values * 4) + " bytes of pixels for " + sizeText(width, height) +
                   ", found " + std::to_string(available));

    RadianceImage image;
    image.width = width;
    image.height = height;
    image.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
    const unsigned char* p = file.data() + pos;
    for (int row = height - 1; row >= 0; --row) {  // bottom row first
        float* out = image.at(0, row);
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) out[3 * x + c] = loadFloat(p + 4 * (channels == 3 ? c : 0), littleEndian);
            p += 4 * channels;
        }
    }
    return image;
}

// ---- Display step ------------------------------------------------------------

std::uint8_t quantize8(double c) {
    if (!(c > 0.0)) return 0;   // c <= 0, and NaN (every comparison with NaN is false)
    if (c >= 1.0) return 255;   // also +Inf
    // std::lround rounds halves away from zero, which for c > 0 is the spec's round(255 c).
    return static_cast<std::uint8_t>(std::lround(255.0 * c));
}

// ---- Comparison ------------------------------------------------------------

namespace {

// Relative difference of radiance, |a - b| / (|b| + kRelFloor). A bare
// |a - b| / |b| is undefined at b = 0 (background, shadow with no ambient)
// and explodes near it, where float rounding alone makes it huge. The floor
// sits well below the smallest radiance a lit or ambient-lit surface has in
// raylab scenes (ambient 0.03 x albedo), so on surfaces this is a true
// relative error, while on black pixels it becomes an absolute error in
// units of 1e-3, which still flags a wrong non-zero value there.
constexpr double kRelFloor = 1e-3;

// The header's relMse denominator: b^2 + 1e-2, i.e. errors are relative for
// |b| above 0.1 and absolute below, as the budget defines it.
constexpr double kRelMseFloor = 1e-2;

// Percentile of the per-pixel max channel difference reported as p99Lsb.
constexpr double kPercentile = 0.99;

void requireSameSize(int w1, int h1, int w2, int h2, const char* what) {
    if (w1 != w2 || h1 != h2)
        throw Error(std::string("cannot compare ") + what + " of different sizes: got " + sizeText(w1, h1) +
                    ", expected " + sizeText(w2, h2));
}

long countNonFinite(const RadianceImage& image) {
    return long(std::count_if(image.rgb.begin(), image.rgb.end(), [](float v) { return !std::isfinite(v); }));
}

double median(std::vector<double>& values) {
    if (values.empty()) return 0.0;
    std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + long(mid), values.end());
    double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    double lower = *std::max_element(values.begin(), values.begin() + long(mid));
    return 0.5 * (lower + upper);
}

}  // namespace

ImageDiff compareRenderings(const Rendering& got, const Rendering& expected) {
    const DisplayImage& a = got.display;
    const DisplayImage& b = expected.display;
    requireSameSize(a.width, a.height, b.width, b.height, "display images");
    for (const DisplayImage* image : {&a, &b}) {
        std::string problem = image->width == 0 && image->height == 0 ? "" : shapeProblem(*image);
        if (!problem.empty()) throw Error("cannot compare display images: " + problem);
    }

    ImageDiff diff;
    const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);

    // 8-bit metrics: per-channel absolute differences in LSB (1/255).
    std::array<std::size_t, 256> maxHistogram{};  // pixels by their max channel difference
    double sumLsb = 0, sumSquares = 0;
    std::size_t off = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c) {
            int d = std::abs(int(a.rgb[3 * p + c]) - int(b.rgb[3 * p + c]));
            pixelMax = std::max(pixelMax, d);
            sumLsb += d;
            sumSquares += double(d) * d;
        }
        ++maxHistogram[std::size_t(pixelMax)];
        if (pixelMax > 1) ++off;  // "off by more than 1/255 in any channel"
        diff.maxLsb = std::max(diff.maxLsb, pixelMax);
    }
    if (pixels > 0) {
        diff.offFraction = double(off) / double(pixels);
        diff.meanLsb = sumLsb / double(3 * pixels);
        // Nearest-rank percentile: the smallest value with at least 99% of pixels at or below it.
        std::size_t rank = std::size_t(std::ceil(kPercentile * double(pixels)));
        std::size_t seen = 0;
        for (std::size_t v = 0; v < maxHistogram.size(); ++v) {
            seen += maxHistogram[v];
            if (seen >= rank) {
                diff.p99Lsb = double(v);
                break;
            }
        }
    }
    double mse = pixels > 0 ? sumSquares / double(3 * pixels) : 0.0;
    diff.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);

    // Radiance metrics, where both renderings carry radiance (a rendering read
    // from a PNG has none). Non-finite values are counted, not averaged.
    const RadianceImage& ra = got.radiance;
    const RadianceImage& rb = expected.radiance;
    diff.nonFinite = countNonFinite(ra) + countNonFinite(rb);
    if (!ra.rgb.empty() && !rb.rgb.empty()) {
        requireSameSize(ra.width, ra.height, rb.width, rb.height, "radiance images");
        for (const RadianceImage* image : {&ra, &rb}) {
            std::string problem = shapeProblem(*image);
            if (!problem.empty()) throw Error("cannot compare radiance images: " + problem);
        }
        std::vector<double> relative;
        relative.reserve(ra.rgb.size());
        double sumRelSquares = 0;
        for (std::size_t k = 0; k < ra.rgb.size(); ++k) {
            double va = ra.rgb[k], vb = rb.rgb[k];
            if (!std::isfinite(va) || !std::isfinite(vb)) continue;
            double d = std::abs(va - vb);
            relative.push_back(d / (std::abs(vb) + kRelFloor));
            sumRelSquares += d * d / (vb * vb + kRelMseFloor);
        }
        if (!relative.empty()) diff.relMse = sumRelSquares / double(relative.size());
        diff.pfmMedianRel = median(relative);
    }
    return diff;
}

DisplayImage differenceHeatMap(const DisplayImage& got, const DisplayImage& expected) {
    requireSameSize(got.width, got.height, expected.width, expected.height, "display images");
    for (const DisplayImage* image : {&got, &expected}) {
        std::string problem = image->width == 0 && image->height == 0 ? "" : shapeProblem(*image);
        if (!problem.empty()) throw Error("cannot compare display images: " + problem);
    }
    // Differences of this many LSB or more show at full yellow: 8 is well
    // past the 1-LSB tolerance of the checks, and a ramp that long keeps the
    // 1- and 2-LSB differences of rounding visibly distinct from real errors.
    constexpr int kSaturationLsb = 8;
    DisplayImage map;
    map.width = got.width;
    map.height = got.height;
    map.rgb.assign(got.rgb.size(), 0);
    for (std::size_t p = 0; p < got.rgb.size() / 3; ++p) {
        int m = 0;
        for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(int(got.rgb[3 * p + c]) - int(expected.rgb[3 * p + c])));
        // Black -> red (half-way) -> yellow (saturated): the "hot" ramp, so the
        // worst pixels are the brightest.
        double t = std::min(m, kSaturationLsb) / double(kSaturationLsb);
        map.rgb[3 * p + 0] = quantize8(2.0 * t);
        map.rgb[3 * p + 1] = quantize8(2.0 * t - 1.0);
        map.rgb[3 * p + 2] = 0;
    }
    return map;
}

}  // namespace rl
