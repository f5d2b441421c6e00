// Environment light (issue 24): the equirectangular radiance map of a scene's
// optional "environment" (docs/scene-format.md), how it is read from a
// Radiance .hdr or a PFM file, and how a direction finds its radiance in it
// (docs/model.md, "Environment light"). Everything here is in double except
// the stored pixels (float, as both file formats hold them).
#pragma once

#include "core/image.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>

namespace rl {

// The largest environment image read: 4096 x 2048 pixels (a "4k" panorama),
// 96 MiB of RGB float once decoded. Bigger files are refused before they are
// decoded (the .hdr header or the file's size says how big they are).
constexpr int kMaxEnvironmentWidth = 4096;
constexpr int kMaxEnvironmentHeight = 4096;
constexpr long long kMaxEnvironmentPixels = 4096LL * 2048LL;
// Radiance values above this are refused: times an intensity up to
// kMaxEnvironmentIntensity it stays far inside float32 for the shader.
constexpr double kMaxEnvironmentValue = 1e15;
constexpr double kMaxEnvironmentIntensity = 1e6;

// A scene's environment: the radiance map, scaled by `intensity` and turned by
// `rotationDegrees` about the world's +y axis (right-handed: 90 brings what
// was seen towards -z to -x).
struct Environment {
    std::string file;                 // as written in the scene file
    std::string path;                 // the file that was read: `file` relative to the scene file's folder
    double intensity = 1.0;
    double rotationDegrees = 0.0;
    std::shared_ptr<const RadianceImage> image;  // never null once loaded; shared by copies of the scene
};

// Reads an equirectangular environment image: Radiance RGBE (.hdr, "#?RADIANCE"
// or "#?RGBE" first line, decoded by stb_image) or PFM (core/image.h readPfm),
// told apart by their first bytes. Row 0 of the result is the top (+y).
// Throws rl::Error "path: cannot read the environment image (reason)" for a
// missing, unreadable, malformed or oversized file (more than
// kMaxEnvironmentPixels or a side above 4096), and for a negative, NaN or
// infinite value or one above kMaxEnvironmentValue.
RadianceImage loadEnvironmentImage(const std::string& path);

// ---- the mapping (docs/model.md, "Environment light") --------------------------
//
// A unit direction d in the image's own frame (y up) maps to
//     u = 1/2 + atan2(d.x, -d.z) / (2 pi)   in [0, 1): u = 1/2 looks along -z, u = 3/4 along +x
//     v = acos(d.y) / pi                     in [0, 1]: v = 0 is straight up (the image's top row)
// and pixel (x, y) covers u in [x/W, (x+1)/W), v in [y/H, (y+1)/H).
glm::dvec2 equirectUv(glm::dvec3 direction);
glm::dvec3 equirectDirection(double u, double v);  // the inverse: a unit vector

// The solid angle of each pixel of row y of a width x height image:
// (2 pi / width) (cos(pi y / height) - cos(pi (y + 1) / height)).
double equirectPixelSolidAngle(int y, int width, int height);

// The image halved: each pixel the mean of a 2 x 2 block weighted by its
// pixels' solid angles, in double, stored as float (an odd side keeps its
// last column or row alone). The pyramids of the prefiltered chain and of
// the cap chain are made of it.
RadianceImage halvedBySolidAngle(const RadianceImage& image);

// The image's own frame from the world: the world direction turned by
// -rotationDegrees about +y.
glm::dvec3 environmentLocalDirection(const Environment& environment, glm::dvec3 worldDirection);
// And back: the world direction of a direction of the image's frame.
glm::dvec3 environmentWorldDirection(const Environment& environment, glm::dvec3 localDirection);

// The radiance map's value at (u, v): bilinear between pixel centres
// ((x + 1/2)/W, (y + 1/2)/H), wrapping around in u, clamped to the first and
// last row in v (what a GL_LINEAR texture with GL_REPEAT in s and
// GL_CLAMP_TO_EDGE in t returns). Not scaled by any intensity.
glm::dvec3 bilinearRadiance(const RadianceImage& image, double u, double v);

// Radiance arriving from the world direction `direction` (unit):
// intensity * bilinearRadiance(image, equirectUv(local direction)).
glm::dvec3 environmentRadiance(const Environment& environment, glm::dvec3 direction);

}  // namespace rl
