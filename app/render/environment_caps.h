// environment_caps.h: the radiance map averaged over caps (issue 34), the
// table shaders/environment_occlusion.glsl reads to know what light a
// sphere's cap of directions would have brought: level k holds, at each
// texel's direction w, the mean radiance over the cap of half-angle
// capLevelAngle(k) around w (every direction of the cap alike, a box on the
// sphere), so that a small sun counts in full wherever it lies inside the
// cap and not at all outside it (a GGX lobe, as the prefiltered chain's,
// would spread it over several times the cap).
#pragma once

#include "core/image.h"

#include <glm/vec3.hpp>

#include <vector>

namespace rl {

// The caps' half-angles: kCapLevels of them, each sqrt(2) times the one
// before, from kSmallestCap (radians) to 90 degrees. THE MODEL'S CONSTANTS (docs/model.md,
// "Occlusion by the spheres"); the shader reads them as uniforms.
inline constexpr int kCapLevels = 13;
inline constexpr double kSmallestCap = 3.14159265358979323846 / 2.0 / 64.0;  // 1.41 degrees
double capLevelAngle(int level);

// The map's sun, where it has one: the pixels within kSunReach of its
// brightest pixel that are at least kSunFloor times as bright, kept only when
// they are compact (at most kSunSolidAngle steradians) and at least
// kSunContrast times the map's mean luminance, and alone: no pixel that
// bright between kSunReach and twice it (a wide source such as a soft box is
// no sun, the cap chain keeps it). The GL picture shadows it as a
// disc of its solid angle (environment_occlusion.glsl), sharp where a cap
// level could only blur it; the cap chain leaves its pixels out.
inline constexpr double kSunReach = 3.14159265358979323846 / 180.0 * 8.0;
inline constexpr double kSunFloor = 0.05;
inline constexpr double kSunSolidAngle = 0.05;
inline constexpr double kSunContrast = 20.0;
struct EnvironmentSun {
    bool present = false;
    glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, image frame: its pixels' centres weighted by luminance times solid angle
    double angularRadius = 0.0;           // of a disc of its solid angle
    glm::dvec3 power{0.0};                // sum of (L - around) dOmega over its pixels (no intensity)
    glm::dvec3 around{0.0};               // the mean radiance of the other pixels within twice kSunReach
    std::vector<int> pixels;              // y * width + x
};
EnvironmentSun findSun(const RadianceImage& image);

// The map with its sun's pixels replaced by the sky around it (`around`):
// what the prefiltered chain and the cap chain are made of, the GL picture
// adding the sun itself as a directional light (shaders/environment.glsl).
// The map itself where it has no sun.
RadianceImage mapWithoutSun(const RadianceImage& image, const EnvironmentSun& sun);

// The chain of `image` (its own frame, no intensity; mapWithoutSun): level k is
// W_k x W_k/2 texels, W_k the power of two nearest 8 pi / capLevelAngle(k)
// (four texels per cap radius), 8 to 256 and at most the image's width. Each
// texel is sum(w_p L_p dOmega_p) / sum(w_p dOmega_p) over the pixels p of the
// image (first summed in 2 x 2 blocks, radiance times solid angle, until it
// is at most 256 wide), w_p = clamp(1/2 + (cap - angle(p, texel)) / pixel, 0, 1)
// with `pixel` one pixel's height in radians: the cap's edge antialiased.
// Each level also holds the means of the caps around both poles, which no
// texel centre reaches (a coarse level's last row lies half a row, up to 11
// degrees, from the pole, where a ground's cap is read).
struct CapLevel {
    RadianceImage means;
    glm::dvec3 north{0.0}, south{0.0};
};
std::vector<CapLevel> capAverageChain(const RadianceImage& image);

// A level's mean at (u, v) of the equirect frame: bilinear between texel
// centres (bilinearRadiance), and between the first or last row and the
// pole's own mean beyond them.
glm::dvec3 capLevelLookup(const CapLevel& level, double u, double v);

}  // namespace rl
