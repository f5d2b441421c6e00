// Environment images: reading .hdr and PFM, and the equirectangular mapping
// (see environment_image.h for the contracts).
#include "core/environment_image.h"

#include "core/error.h"
#include "core/file_io.h"
#include "core/message.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

// stb_image, as in core/image.cpp: compiled into this one file with static
// functions and no file I/O of its own, here for the Radiance .hdr decoder
// only (image.cpp's copy decodes PNG only; both are private to their file).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_ONLY_HDR
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wtype-limits"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A PFM of the largest legal size, with room for its header: larger files are
// refused unread. An RGBE .hdr is at most 4 bytes a pixel (less when run-length coded).
constexpr std::uintmax_t kMaxEnvironmentFileBytes = std::uintmax_t(kMaxEnvironmentPixels) * 12 + 4096;

std::string sizeText(long long w, long long h) { return std::to_string(w) + "x" + std::to_string(h); }

void requireSize(long long w, long long h, const std::string& path) {
    if (w > kMaxEnvironmentWidth || h > kMaxEnvironmentHeight || w * h > kMaxEnvironmentPixels)
        throw Error(path + ": cannot read the environment image (it is " + sizeText(w, h) +
                    " pixels, more than the limit of " + std::to_string(kMaxEnvironmentPixels) +
                    " pixels, 4096x2048, and 4096 a side)");
}

// stb_image's run-length decoder loops forever on a run of length 0, and on
// a truncated file (it reads zeros past the end): seen with a .hdr cut short.
// So the scanlines are walked here first, as stb will walk them, and a file
// that would make it loop is refused. "" when stb can decode it safely.
std::string hdrScanlineProblem(const std::string& bytes, int width, int height) {
    std::size_t pos = bytes.find("\n\n");  // the header ends with an empty line...
    if (pos == std::string::npos) return "no end of header";
    pos = bytes.find('\n', pos + 2);     // ...then comes "-Y height +X width"
    if (pos == std::string::npos) return "no resolution line";
    ++pos;
    if (width < 8 || width >= 32768) return "";  // stb reads these flat: it stops at the end of the data
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    for (int row = 0; row < height; ++row) {
        if (pos + 4 > bytes.size()) return "the file ends at scanline " + std::to_string(row);
        if (byte(pos) != 2 || byte(pos + 1) != 2 || (byte(pos + 2) & 0x80)) return "";  // flat from here: safe
        pos += 4;  // stb checks the scanline's length itself
        for (int component = 0; component < 4; ++component) {
            int filled = 0;
            while (filled < width) {
                if (pos >= bytes.size()) return "the file ends at scanline " + std::to_string(row);
                int count = byte(pos++);
                if (count == 0) return "a run of length 0 at scanline " + std::to_string(row);
                if (count > 128) {
                    count -= 128;
                    ++pos;
                } else {
                    pos += std::size_t(count);
                }
                if (count > width - filled) return "";  // stb reports "bad RLE data" itself
                filled += count;
            }
            if (pos > bytes.size()) return "the file ends at scanline " + std::to_string(row);
        }
    }
    return "";
}

// The resolution line of a .hdr, read here before stb_image sees it: stb
// reads "-Y H +X W" with strtol and casts to int, so 4294967300 wraps to 4,
// and a 0 or a missing number crashes its decoder (a division by the width,
// a write past a 0-row image). Each number must be written in 1 to 9 decimal
// digits and be at least 1; stb's orientation is the only one it decodes.
void requireHdrResolution(const std::string& bytes, const std::string& path) {
    std::size_t pos = bytes.find("\n\n");
    if (pos == std::string::npos) return;  // stb refuses the file itself
    pos += 2;
    const std::size_t end = std::min(bytes.find('\n', pos), std::min(bytes.size(), pos + 64));
    const std::string line = bytes.substr(pos, end - pos);
    auto refuse = [&](const std::string& why) {
        throw Error(path + ": cannot read the environment image (its resolution line " + quotedValue(line) + " " + why + ")");
    };
    if (line.compare(0, 3, "-Y ") != 0) refuse("is not \"-Y height +X width\", the orientation raylab reads");
    auto number = [&](std::size_t& at, const char* what) {
        std::size_t digits = 0;
        long long value = 0;
        while (at < line.size() && line[at] >= '0' && line[at] <= '9' && digits < 10) {
            value = value * 10 + (line[at++] - '0');
            ++digits;
        }
        if (digits == 0) refuse(std::string("has no ") + what);
        if (digits > 9 || (at < line.size() && line[at] >= '0' && line[at] <= '9'))
            refuse(std::string("gives a ") + what + " too large to be an image's");
        if (value < 1) refuse(std::string("gives a ") + what + " of 0: an image has at least one pixel a side");
        return value;
    };
    std::size_t at = 3;
    const long long height = number(at, "height");
    if (line.compare(at, 4, " +X ") != 0) refuse("is not \"-Y height +X width\", the orientation raylab reads");
    at += 4;
    const long long width = number(at, "width");
    if (at != line.size()) refuse("has more after the width");
    requireSize(width, height, path);  // before decoding: a lying header cannot ask for gigabytes
}

RadianceImage decodeHdr(const std::string& bytes, const std::string& path) {
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    int length = int(bytes.size());  // bytes.size() <= kMaxEnvironmentFileBytes < 2^31
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &w, &h, &channels))
        throw Error(path + ": cannot read the environment image (" + stbi_failure_reason() + ")");
    requireHdrResolution(bytes, path);
    requireSize(w, h, path);
    std::string problem = hdrScanlineProblem(bytes, w, h);
    if (!problem.empty()) throw Error(path + ": cannot read the environment image (corrupt HDR: " + problem + ")");
    float* pixels = stbi_loadf_from_memory(data, length, &w, &h, &channels, 3);
    if (!pixels) throw Error(path + ": cannot read the environment image (" + stbi_failure_reason() + ")");
    RadianceImage image;
    image.width = w;
    image.height = h;
    image.rgb.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 3);  // row 0 = top, as image.h
    stbi_image_free(pixels);
    return image;
}

bool startsWith(const std::string& bytes, const char* prefix) {
    return bytes.compare(0, std::strlen(prefix), prefix) == 0;
}

}  // namespace

RadianceImage loadEnvironmentImage(const std::string& path) {
    // Not found, a folder, a FIFO, too large: one line, nothing decoded.
    std::string bytes = readRegularFile(path, kMaxEnvironmentFileBytes, "the environment image");
    RadianceImage image;
    if (startsWith(bytes, "#?RADIANCE") || startsWith(bytes, "#?RGBE")) {
        image = decodeHdr(bytes, path);
    } else if (startsWith(bytes, "PF") || startsWith(bytes, "Pf")) {
        try {
            image = readPfm(path);
        } catch (const Error& e) {  // "path: cannot read PFM (reason)"
            std::string what = e.what();
            std::string prefix = path + ": cannot read PFM";
            if (what.compare(0, prefix.size(), prefix) == 0)
                what = path + ": cannot read the environment image, a PFM" + what.substr(prefix.size());
            throw Error(what);
        }
        requireSize(image.width, image.height, path);
    } else {
        throw Error(path + ": cannot read the environment image (neither a Radiance .hdr, which starts with "
                           "\"#?RADIANCE\", nor a PFM, which starts with \"PF\")");
    }
    for (std::size_t k = 0; k < image.rgb.size(); ++k) {
        float value = image.rgb[k];
        if (!(value >= 0.0f && value <= kMaxEnvironmentValue)) {  // also NaN
            std::size_t pixel = k / 3;
            throw Error(path + ": cannot read the environment image (pixel (" +
                        std::to_string(pixel % std::size_t(image.width)) + ", " +
                        std::to_string(pixel / std::size_t(image.width)) + ") holds " + std::to_string(value) +
                        ": radiance must be finite, >= 0 and at most 1e15)");
        }
    }
    return image;
}

glm::dvec2 equirectUv(glm::dvec3 d) {
    double u = 0.5 + std::atan2(d.x, -d.z) / (2.0 * kPi);
    if (u >= 1.0) u -= 1.0;  // atan2 = pi exactly (looking along +z) gives u = 1: the same column as u = 0
    double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    return {u, v};
}

glm::dvec3 equirectDirection(double u, double v) {
    double phi = (u - 0.5) * 2.0 * kPi;
    double theta = v * kPi;
    double s = std::sin(theta);
    return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

double equirectPixelSolidAngle(int y, int width, int height) {
    return 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
}

RadianceImage halvedBySolidAngle(const RadianceImage& a) {
    RadianceImage b;
    b.width = (a.width + 1) / 2;
    b.height = (a.height + 1) / 2;
    b.rgb.assign(std::size_t(b.width) * std::size_t(b.height) * 3, 0.0f);
    std::vector<double> sum(b.rgb.size(), 0.0), weight(std::size_t(b.width) * std::size_t(b.height), 0.0);
    for (int y = 0; y < a.height; ++y) {
        const double omega = equirectPixelSolidAngle(y, a.width, a.height);
        for (int x = 0; x < a.width; ++x) {
            const std::size_t k = std::size_t(y / 2) * std::size_t(b.width) + std::size_t(x / 2);
            for (int c = 0; c < 3; ++c) sum[3 * k + std::size_t(c)] += omega * a.at(x, y)[c];
            weight[k] += omega;
        }
    }
    for (std::size_t k = 0; k < weight.size(); ++k)
        for (int c = 0; c < 3; ++c)
            b.rgb[3 * k + std::size_t(c)] = weight[k] > 0.0 ? float(sum[3 * k + std::size_t(c)] / weight[k]) : 0.0f;
    return b;
}

namespace {
glm::dvec3 rotateY(glm::dvec3 d, double degrees) {
    if (degrees == 0.0) return d;  // exact: no rounding of sin/cos for the unrotated map
    double a = degrees * kPi / 180.0;
    double c = std::cos(a), s = std::sin(a);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}
}  // namespace

glm::dvec3 environmentLocalDirection(const Environment& environment, glm::dvec3 worldDirection) {
    return rotateY(worldDirection, -environment.rotationDegrees);
}

glm::dvec3 environmentWorldDirection(const Environment& environment, glm::dvec3 localDirection) {
    return rotateY(localDirection, environment.rotationDegrees);
}

glm::dvec3 bilinearRadiance(const RadianceImage& image, double u, double v) {
    const int W = image.width, H = image.height;
    double x = u * W - 0.5;
    double y = std::clamp(v * H - 0.5, 0.0, double(H - 1));
    double fx = std::floor(x), fy = std::floor(y);
    double ax = x - fx, ay = y - fy;
    int x0 = int(fx) % W;
    if (x0 < 0) x0 += W;
    int x1 = (x0 + 1) % W;
    int y0 = int(fy);
    int y1 = std::min(y0 + 1, H - 1);
    auto at = [&](int px, int py) {
        const float* p = image.at(px, py);
        return glm::dvec3(p[0], p[1], p[2]);
    };
    return (1.0 - ay) * ((1.0 - ax) * at(x0, y0) + ax * at(x1, y0)) + ay * ((1.0 - ax) * at(x0, y1) + ax * at(x1, y1));
}

glm::dvec3 environmentRadiance(const Environment& environment, glm::dvec3 direction) {
    glm::dvec2 uv = equirectUv(environmentLocalDirection(environment, direction));
    return environment.intensity * bilinearRadiance(*environment.image, uv.x, uv.y);
}

}  // namespace rl
