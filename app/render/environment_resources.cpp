// environment_resources.cpp: see environment_resources.h.
#include "render/environment_resources.h"

#include "core/error.h"
#include "reference/split_sum.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

namespace rl {

namespace {

void checkSettings(const EnvironmentSettings& s) {
    auto bad = [](const std::string& what) { throw Error("environment settings: " + what); };
    if (s.levels < 2 || s.levels > 16) bad("levels must be 2 to 16");
    if (s.prefilterWidth < 8 || s.prefilterHeight < 4 || s.prefilterWidth > 4096 || s.prefilterHeight > 2048)
        bad("the prefiltered size must be 8 x 4 to 4096 x 2048");
    if (s.prefilterSamples < 1 || s.prefilterSamples > 65536) bad("prefilter samples must be 1 to 65536");
    if (s.tableSize < 2 || s.tableSize > 512) bad("the table size must be 2 to 512");
    if (s.tableSamples < 1 || s.tableSamples > 1024) bad("table samples must be 1 to 1024");
    if (s.irradianceMap != 0 && (s.irradianceMap < 2 || s.irradianceMap > 512 || s.irradianceMap % 2 != 0))
        bad("the irradiance map's width must be 0 (SH9) or an even number from 2 to 512");
}

// The table depends on the settings only; the rest on the image too.
std::vector<glm::dvec2> cachedTable(int size, int samples) {
    static std::mutex mutex;
    static std::map<std::pair<int, int>, std::vector<glm::dvec2>> tables;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = tables.find({size, samples});
    if (it == tables.end()) it = tables.emplace(std::make_pair(size, samples), ref::splitSumTable(size, samples)).first;
    return it->second;
}

}  // namespace

RadianceImage environmentIrradianceMap(const RadianceImage& image, int width) {
    if (width < 2 || width > 512 || width % 2 != 0)
        throw Error("irradiance map: the width must be an even number from 2 to 512, not " + std::to_string(width));
    const int W = image.width, H = image.height;
    // Each source pixel's (or f x f block's) direction and radiance times solid angle.
    int f = 1;
    while (W / f > 512) f *= 2;
    struct Source {
        glm::dvec3 w;
        glm::dvec3 lOmega;
    };
    std::vector<Source> sources;
    for (int by = 0; by < H; by += f)
        for (int bx = 0; bx < W; bx += f) {
            glm::dvec3 w(0.0), lOmega(0.0);
            for (int y = by; y < std::min(by + f, H); ++y) {
                const double omega = equirectPixelSolidAngle(y, W, H);
                const double v = (y + 0.5) / H;
                for (int x = bx; x < std::min(bx + f, W); ++x) {
                    const float* L = image.at(x, y);
                    w += omega * equirectDirection((x + 0.5) / W, v);
                    lOmega += omega * glm::dvec3(L[0], L[1], L[2]);
                }
            }
            if (lOmega == glm::dvec3(0.0)) continue;  // adds nothing to any texel
            sources.push_back({glm::normalize(w), lOmega});
        }
    RadianceImage out;
    out.width = width;
    out.height = width / 2;
    out.rgb.assign(std::size_t(out.width) * out.height * 3, 0.0f);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const glm::dvec3 n = equirectDirection((x + 0.5) / out.width, (y + 0.5) / out.height);
            glm::dvec3 E(0.0);
            for (const Source& s : sources) {
                const double c = n.x * s.w.x + n.y * s.w.y + n.z * s.w.z;
                if (c > 0.0) E += c * s.lOmega;
            }
            float* e = out.at(x, y);
            for (int c = 0; c < 3; ++c) e[c] = float(E[c]);
        }
    return out;
}

std::shared_ptr<const EnvironmentResources> environmentResources(const Environment& environment,
                                                                 const EnvironmentSettings& settings) {
    checkSettings(settings);
    if (!environment.image) throw Error(environment.file + ": the environment image is not loaded");
    struct Entry {
        std::weak_ptr<const RadianceImage> image;
        EnvironmentSettings settings;
        std::shared_ptr<const EnvironmentResources> resources;
    };
    static std::mutex mutex;
    static std::vector<Entry> cache;
    {
        std::lock_guard<std::mutex> lock(mutex);
        cache.erase(std::remove_if(cache.begin(), cache.end(), [](const Entry& e) { return e.image.expired(); }),
                    cache.end());
        for (const Entry& e : cache)
            if (e.image.lock() == environment.image && e.settings == settings) return e.resources;
    }
    auto r = std::make_shared<EnvironmentResources>();
    r->settings = settings;
    r->map = environment.image;
    r->sun = findSun(*environment.image);
    // The tables of the sky without its sun: the picture adds the sun as a
    // light of its own (shaders/environment.glsl, sunLight); SH9 stays the
    // whole map's, exercise 11's coefficients, the sun's three bands taken
    // out in the shader.
    // (A copy only where there is a sun to take out.)
    RadianceImage withoutSun;
    if (r->sun.present) withoutSun = mapWithoutSun(*environment.image, r->sun);
    const RadianceImage& sunless = r->sun.present ? withoutSun : *environment.image;
    r->levels = ref::prefilterChain(sunless, settings.prefilterWidth, settings.prefilterHeight, settings.levels,
                                    settings.prefilterSamples);
    r->sh = ref::projectSh9(*environment.image);
    r->table = cachedTable(settings.tableSize, settings.tableSamples);
    if (settings.irradianceMap > 0) r->irradiance = environmentIrradianceMap(sunless, settings.irradianceMap);
    r->caps = capVolume(capAverageChain(sunless));
    std::lock_guard<std::mutex> lock(mutex);
    cache.push_back({environment.image, settings, r});
    return r;
}

std::vector<glm::ivec4> environmentAtlasRects(const std::vector<RadianceImage>& levels) {
    std::vector<glm::ivec4> rects;
    int y = 0;
    for (const RadianceImage& level : levels) {
        rects.emplace_back(0, y, level.width, level.height);
        y += level.height;
    }
    return rects;
}

CapVolume capVolume(const std::vector<CapLevel>& caps) {
    CapVolume v;
    for (const CapLevel& cap : caps) {
        const RadianceImage& level = cap.means;
        v.width = std::max(v.width, level.width);
        v.height = std::max(v.height, level.height);
    }
    v.levels = int(caps.size());
    v.rgba.reserve(std::size_t(v.width) * std::size_t(v.height) * caps.size() * 4);
    float largest = 0.0f;
    for (std::size_t k = 0; k < caps.size(); ++k) {
        const double solidAngle = 1.0 - std::cos(capLevelAngle(int(k)));  // over 2 pi
        for (int y = 0; y < v.height; ++y)
            for (int x = 0; x < v.width; ++x) {
                const glm::dvec3 L = capLevelLookup(caps[k], (x + 0.5) / v.width, (y + 0.5) / v.height);
                for (int c = 0; c < 3; ++c) {
                    v.rgba.push_back(float(L[c] * solidAngle));
                    largest = std::max(largest, v.rgba.back());
                }
                v.rgba.push_back(1.0f);
            }
    }
    if (largest > 0.0f && std::isfinite(largest)) {
        v.scale = largest;
        for (std::size_t i = 0; i < v.rgba.size(); ++i)
            if (i % 4 != 3) v.rgba[i] /= largest;
    }
    return v;
}

EnvironmentTextures::EnvironmentTextures(std::shared_ptr<const EnvironmentResources> resources)
    : resources_(std::move(resources)) {
    const EnvironmentResources& r = *resources_;
    rects_ = environmentAtlasRects(r.levels);
    int atlasWidth = 0, atlasHeight = 0;
    for (const glm::ivec4& rect : rects_) {
        atlasWidth = std::max(atlasWidth, rect.z);
        atlasHeight = rect.y + rect.w;
    }
    std::vector<float> atlas(std::size_t(atlasWidth) * atlasHeight * 3, 0.0f);
    for (std::size_t k = 0; k < r.levels.size(); ++k)
        for (int y = 0; y < rects_[k].w; ++y)
            std::copy_n(r.levels[k].at(0, y), 3 * rects_[k].z, &atlas[3 * (std::size_t(rects_[k].y + y) * atlasWidth)]);
    std::vector<float> table;
    for (const glm::dvec2& e : r.table) {
        table.push_back(float(e.x));
        table.push_back(float(e.y));
    }
    GLint maxSide = 0;
    gl::GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSide);
    if (r.map->width > maxSide || r.map->height > maxSide || atlasHeight > maxSide)
        throw Error("environment image " + std::to_string(r.map->width) + "x" + std::to_string(r.map->height) +
                    ": this OpenGL driver allows at most " + std::to_string(maxSide) + " pixels a side");
    gl::GenTextures(r.irradiance.width > 0 ? 4 : 3, textures_);
    auto upload = [](GLuint texture, GLint format, GLenum channels, int w, int h, const float* data) {
        gl::BindTexture(GL_TEXTURE_2D, texture);
        gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl::TexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, channels, GL_FLOAT, data);
        // texelFetch() only: NEAREST keeps a float texture complete where it cannot be filtered (WebGL2).
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    };
    upload(textures_[0], GL_RGB32F, GL_RGB, r.map->width, r.map->height, r.map->rgb.data());
    upload(textures_[1], GL_RGB32F, GL_RGB, atlasWidth, atlasHeight, atlas.data());
    upload(textures_[2], GL_RG32F, GL_RG, r.settings.tableSize, r.settings.tableSize, table.data());
    if (r.irradiance.width > 0) {  // RGBA32F (alpha 1): the four-channel float format every GL and WebGL2 samples
        std::vector<float> rgba;
        rgba.reserve(r.irradiance.rgb.size() / 3 * 4);
        for (std::size_t p = 0; p < r.irradiance.rgb.size(); p += 3) {
            const auto first = r.irradiance.rgb.begin() + std::ptrdiff_t(p);
            rgba.insert(rgba.end(), first, first + 3);
            rgba.push_back(1.0f);
        }
        upload(textures_[3], GL_RGBA32F, GL_RGBA, r.irradiance.width, r.irradiance.height, rgba.data());
    }
    gl::BindTexture(GL_TEXTURE_2D, 0);
    const CapVolume& caps = r.caps;
    gl::GenTextures(1, &caps_);
    gl::BindTexture(GL_TEXTURE_3D, caps_);
    gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl::TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA16F, caps.width, caps.height, caps.levels, 0, GL_RGBA, GL_FLOAT,
                   caps.rgba.data());
    // Trilinear: bilinear between texel centres in each level as every other
    // lookup (around in u, clamped in v), and the two levels around a cap's
    // angle mixed linearly (their integrals over the cap, as capVolume holds).
    gl::TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl::TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl::TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl::TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    gl::BindTexture(GL_TEXTURE_3D, 0);
    GLenum error = gl::GetError();
    if (error != GL_NO_ERROR) throw Error("environment textures: OpenGL error " + gl::errorName(error));
}

EnvironmentTextures::~EnvironmentTextures() {
    gl::DeleteTextures(textures_[3] != 0 ? 4 : 3, textures_);
    gl::DeleteTextures(1, &caps_);
}

void EnvironmentTextures::bind(const ShaderProgram& p, const Environment& environment) const {
    gl::UseProgram(p.id());
    const char* samplers[3] = {"u_envMap", "u_envPrefiltered", "u_envSplitSum"};
    for (int i = 0; i < 3; ++i) {
        gl::ActiveTexture(GL_TEXTURE0 + kFirstUnit + i);
        gl::BindTexture(GL_TEXTURE_2D, textures_[i]);
        gl::Uniform1i(p.uniform(samplers[i]), kFirstUnit + i);
    }
    if (textures_[3] != 0) {  // only a program with RL_ENV_IRRADIANCE_MAP has u_envIrradiance
        gl::ActiveTexture(GL_TEXTURE0 + kFirstUnit + 3);
        gl::BindTexture(GL_TEXTURE_2D, textures_[3]);
        gl::Uniform1i(p.uniform("u_envIrradiance"), kFirstUnit + 3);
    }
    if (p.uniform("u_envCaps") >= 0) {  // only a program with RL_ENV_OCCLUSION reads it
        gl::ActiveTexture(GL_TEXTURE0 + kFirstUnit + 4);
        gl::BindTexture(GL_TEXTURE_3D, caps_);
        gl::Uniform1i(p.uniform("u_envCaps"), kFirstUnit + 4);
    }
    gl::ActiveTexture(GL_TEXTURE0);
    for (std::size_t k = 0; k < rects_.size(); ++k) {
        const glm::ivec4& r = rects_[k];
        gl::Uniform4f(p.uniform("u_envLevelRect[" + std::to_string(k) + "]"), float(r.x), float(r.y), float(r.z),
                      float(r.w));
    }
    gl::Uniform1i(p.uniform("u_envLevels"), int(rects_.size()));
    gl::Uniform1i(p.uniform("u_envCapLevels"), resources_->caps.levels);
    gl::Uniform1f(p.uniform("u_envCapScale"), resources_->caps.scale);
    float sh[27];
    for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) sh[3 * k + c] = float(resources_->sh[std::size_t(k)][c]);
    gl::Uniform3fv(p.uniform("u_envSh"), 9, sh);
    gl::Uniform1f(p.uniform("u_envIntensity"), float(environment.intensity));
    // cos and sin of the rotation, in double; exactly (1, 0) unrotated, as the reference.
    double a = environment.rotationDegrees * 3.14159265358979323846 / 180.0;
    gl::Uniform2f(p.uniform("u_envRotation"), environment.rotationDegrees == 0.0 ? 1.0f : float(std::cos(a)),
                  environment.rotationDegrees == 0.0 ? 0.0f : float(std::sin(a)));
    gl::Uniform1f(p.uniform("u_envSmallestCap"), float(capLevelAngle(0)));
    const EnvironmentSun& sun = resources_->sun;  // turned into the world: R_y(rotation), environmentLocal's inverse
    const double c = environment.rotationDegrees == 0.0 ? 1.0 : std::cos(a), s = environment.rotationDegrees == 0.0 ? 0.0 : std::sin(a);
    const glm::dvec3 d = sun.direction;
    gl::Uniform4f(p.uniform("u_envSun"), float(c * d.x + s * d.z), float(d.y), float(-s * d.x + c * d.z),
                  sun.present ? float(sun.angularRadius) : 0.0f);
    gl::Uniform3f(p.uniform("u_envSunPower"), float(sun.power.x), float(sun.power.y), float(sun.power.z));
}

}  // namespace rl
