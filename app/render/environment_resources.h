// What the GL picture needs for a scene's environment (issue 24,
// shaders/environment.glsl): the host's tables, computed in double by the
// reference's sh9.* and split_sum.* and uploaded as textures and uniforms.
// THE HOST SIDE OF THE SHADER API (docs/decisions.md, "Environment light in
// the GL picture"):
//   environmentResources(environment, settings)  the tables, cached per image and settings
//   EnvironmentTextures(resources)               their textures (needs a current context)
//   EnvironmentTextures::bind(program, environment)  textures to units 1-5 and every u_env* uniform;
//                                               intensity and rotation are read from `environment`
//                                               each call (values: no recompile, no new tables)
// GlRenderer::setScene() builds them for a scene with an environment and
// draw() binds them, so every caller of GlRenderer draws environment scenes.
#pragma once

#include "core/environment_image.h"
#include "gl/gl_api.h"
#include "render/environment_caps.h"
#include "reference/sh9.h"
#include "shader/program.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace rl {

// The approximation's sizes (what the bench sweeps). Defaults: docs/decisions.md.
struct EnvironmentSettings {
    int prefilterWidth = 128;   // the sharpest levels of the prefiltered chain (the rougher as wide as their lobe needs, ref::prefilterChain)
    int prefilterHeight = 64;
    int levels = 16;            // level k for roughness k / (levels - 1); 2 to 16 (ENV_MAX_LEVELS, shaders/environment.glsl)
    int prefilterSamples = 128; // GGX-distributed directions per prefiltered texel (Hammersley)
    int tableSize = 32;         // the split-sum table: tableSize x tableSize entries
    int tableSamples = 32;      // tableSamples^2 half vectors per entry
    // 0: diffuse irradiance from the nine SH coefficients (the course's
    // default, exercise 11). N (16 to 512, even): also an N x N/2 equirect
    // irradiance map (environmentIrradianceMap), which shaders/environment.glsl
    // reads instead of SH9 only where RL_ENV_IRRADIANCE_MAP is defined (the
    // bench's env:irradiance-map=N rows); every other program ignores it.
    int irradianceMap = 0;
    bool operator==(const EnvironmentSettings& o) const {
        return prefilterWidth == o.prefilterWidth && prefilterHeight == o.prefilterHeight && levels == o.levels &&
               prefilterSamples == o.prefilterSamples && tableSize == o.tableSize && tableSamples == o.tableSamples &&
               irradianceMap == o.irradianceMap;
    }
};

// The cap chain as one volume (environment_occlusion.glsl reads it with one
// trilinear lookup, the two cap levels around a cap's angle mixed by the
// filter): level k's integral over its cap, its mean radiance times
// 1 - cos(capLevelAngle(k)) (the solid angle over 2 pi), so that the mix
// between two levels weighs each by its cap, as a sum of light. Every level
// is resampled, bilinearly as the shader's lookups read it, to the widest
// level's size (width x height texels, `levels` layers, RGBA, alpha 1) and
// divided by `scale`, the largest value, so that a half-float texture
// (filterable by every GL and WebGL2: 11 bits, within 0.05% of each value
// above 6e-5 of the largest) holds any legal map.
struct CapVolume {
    int width = 0, height = 0, levels = 0;
    float scale = 1.0f;
    std::vector<float> rgba;
};
CapVolume capVolume(const std::vector<CapLevel>& caps);

struct EnvironmentResources {
    EnvironmentSettings settings;
    std::shared_ptr<const RadianceImage> map;  // the radiance map as read (no intensity, image frame)
    std::vector<RadianceImage> levels;         // ref::prefilterChain
    ref::Sh9 sh;                               // ref::projectSh9
    std::vector<glm::dvec2> table;             // ref::splitSumTable, tableSize^2 (scale, bias)
    RadianceImage irradiance;                  // environmentIrradianceMap(map, settings.irradianceMap); empty for 0
    EnvironmentSun sun;                        // findSun(map) (environment_caps.h): the picture's sun light and its shadow
    CapVolume caps;                            // capVolume(capAverageChain(mapWithoutSun(map, sun))): the same
};

// The irradiance map of `image` (its own frame, no intensity): width x
// width/2 texels, texel (x, y) holding E(n) = sum over the image's pixels of
// L_p max(0, n . w_p) dOmega_p, n the direction of the texel's centre
// (equirectDirection((x + 1/2)/width, (y + 1/2)/(width/2))), w_p and dOmega_p
// the direction of pixel p's centre and its exact solid angle
// (2 pi / W) (cos theta_top - cos theta_bottom); in double, stored as float.
// So a uniform map of radiance L gives E = pi L up to the pixels' cosine
// quadrature (tests/unit/test_irradiance_map.cpp). Images wider than 512
// pixels are first summed in f x f blocks (radiance times solid angle, the
// block's direction the solid-angle-weighted mean) so that a 4k map costs no
// more than a 512 x 256 one. Throws rl::Error for a width out of 2..512 or odd.
RadianceImage environmentIrradianceMap(const RadianceImage& image, int width);

// The tables of `environment`'s image for `settings` (throws rl::Error for
// settings out of range). Cached while the image lives: a second scene with
// the same image, or the same scene at another rotation or intensity, reuses them.
std::shared_ptr<const EnvironmentResources> environmentResources(const Environment& environment,
                                                                 const EnvironmentSettings& settings = {});

// The atlas of the prefiltered levels: level k's texel rectangle (x, y,
// width, height); the levels stacked top to bottom, each at x = 0.
std::vector<glm::ivec4> environmentAtlasRects(const std::vector<RadianceImage>& levels);

class EnvironmentTextures {
public:
    explicit EnvironmentTextures(std::shared_ptr<const EnvironmentResources> resources);
    ~EnvironmentTextures();
    EnvironmentTextures(const EnvironmentTextures&) = delete;
    EnvironmentTextures& operator=(const EnvironmentTextures&) = delete;

    // Binds the textures to units 1, 2, 3 (4: the irradiance map, where the
    // settings have one; 5: the cap volume) and sets every u_env* (u_envCaps,
    // u_envCapLevels, u_envCapScale, u_envSmallestCap: the cap chain;
    // u_envSun, u_envSunPower: the sun in world directions; for
    // environment_occlusion.glsl)
    // uniform of `program` (the program is made current).
    void bind(const ShaderProgram& program, const Environment& environment) const;
    const EnvironmentResources& resources() const { return *resources_; }

    static constexpr int kFirstUnit = 1;  // unit 0 stays the probe inputs' and the callers'

private:
    std::shared_ptr<const EnvironmentResources> resources_;
    GLuint textures_[4] = {0, 0, 0, 0};  // map, prefiltered atlas, split-sum table, irradiance map (or 0)
    GLuint caps_ = 0;                   // EnvironmentResources::caps, a 3D texture
    std::vector<glm::ivec4> rects_;     // the prefiltered levels' in the atlas
};

}  // namespace rl
