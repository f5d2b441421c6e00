// What the GL picture needs for a scene's environment (issue 24,
// shaders/environment.glsl): the host's tables, computed in double by the
// reference's sh9.* and split_sum.* and uploaded as textures and uniforms.
// THE HOST SIDE OF THE SHADER API (docs/decisions.md, "Environment light in
// the GL picture"):
//   environmentResources(environment, settings)  the tables, cached per image and settings
//   EnvironmentTextures(resources)               their textures (needs a current context)
//   EnvironmentTextures::bind(program, environment)  textures to units 1-3 and every u_env* uniform;
//                                               intensity and rotation are read from `environment`
//                                               each call (values: no recompile, no new tables)
// GlRenderer::setScene() builds them for a scene with an environment and
// draw() binds them, so every caller of GlRenderer draws environment scenes.
#pragma once

#include "core/environment_image.h"
#include "gl/gl_api.h"
#include "reference/sh9.h"
#include "shader/program.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace rl {

// The approximation's sizes (what the bench sweeps). Defaults: docs/decisions.md.
struct EnvironmentSettings {
    int prefilterWidth = 128;   // level 0 of the prefiltered chain (each level halves, never below 8 x 4)
    int prefilterHeight = 64;
    int levels = 6;             // level k for roughness k / (levels - 1); 2 to 8 (ENV_MAX_LEVELS, shaders/environment.glsl)
    int prefilterSamples = 128; // GGX-distributed directions per prefiltered texel (Hammersley)
    int tableSize = 32;         // the split-sum table: tableSize x tableSize entries
    int tableSamples = 32;      // tableSamples^2 half vectors per entry
    bool operator==(const EnvironmentSettings& o) const {
        return prefilterWidth == o.prefilterWidth && prefilterHeight == o.prefilterHeight && levels == o.levels &&
               prefilterSamples == o.prefilterSamples && tableSize == o.tableSize && tableSamples == o.tableSamples;
    }
};

struct EnvironmentResources {
    EnvironmentSettings settings;
    std::shared_ptr<const RadianceImage> map;  // the radiance map as read (no intensity, image frame)
    std::vector<RadianceImage> levels;         // ref::prefilterChain
    ref::Sh9 sh;                               // ref::projectSh9
    std::vector<glm::dvec2> table;             // ref::splitSumTable, tableSize^2 (scale, bias)
};

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

    // Binds the three textures to units 1, 2, 3 and sets every u_env*
    // uniform of `program` (the program is made current).
    void bind(const ShaderProgram& program, const Environment& environment) const;
    const EnvironmentResources& resources() const { return *resources_; }

    static constexpr int kFirstUnit = 1;  // unit 0 stays the probe inputs' and the callers'

private:
    std::shared_ptr<const EnvironmentResources> resources_;
    GLuint textures_[3] = {0, 0, 0};  // map, prefiltered atlas, split-sum table
    std::vector<glm::ivec4> rects_;
};

}  // namespace rl
