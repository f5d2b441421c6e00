// Scene: the data model of docs/model.md, in double
// precision. The JSON loader (scene_io.cpp) fills it and validates it; the
// renderer, the CPU reference and every check read it.
#pragma once

#include "core/environment_image.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rl {

// Model variants (accuracy issue). The reference model is the default of each.
enum class DistributionModel { GGX, Beckmann };
enum class GeometryModel { SchlickGGX, SmithGGXSeparable, SmithGGXCorrelated };
enum class FresnelModel { Schlick, Dielectric, Conductor };
enum class DiffuseModel { Lambert, Burley };

struct ShadingModel {
    DistributionModel distribution = DistributionModel::GGX;
    GeometryModel geometry = GeometryModel::SchlickGGX;
    FresnelModel fresnel = FresnelModel::Schlick;
    DiffuseModel diffuse = DiffuseModel::Lambert;
    bool blinnPhong = false;  // whole-model switch: Blinn-Phong instead of PBR
    bool isReference() const {
        return distribution == DistributionModel::GGX && geometry == GeometryModel::SchlickGGX &&
               fresnel == FresnelModel::Schlick && diffuse == DiffuseModel::Lambert && !blinnPhong;
    }
};

struct Material {
    glm::dvec3 albedo{1.0, 1.0, 1.0};  // linear base colour
    double roughness = 0.5;            // perceptual roughness, clamped to [0.045, 1] when shading
    double metallic = 0.0;
    double ao = 1.0;                   // ambient occlusion, scales the ambient term only
    glm::dvec3 edgeTint{1.0, 1.0, 1.0};  // conductor Fresnel only (Gulbrandsen 2014 g)
};

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 1.0;
    Material material;
};

struct Light {
    glm::dvec3 position{0.0};
    glm::dvec3 color{1.0, 1.0, 1.0};
    double intensity = 1.0;
};

struct Camera {
    glm::dvec3 position{0.0, 0.0, 0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDegrees = 60.0;  // full vertical field of view
};

enum class ToneMap { Reinhard, Exponential, None };

struct RenderSettings {
    int width = 640;
    int height = 480;
    int maxBounces = 2;   // mirror bounces after the primary hit
    int spp = 1;          // samples per pixel, a square number
    double ambient = 0.03;
    glm::dvec3 background{0.0};
    double exposure = 1.0;
    ToneMap tonemap = ToneMap::Reinhard;
    double gamma = 2.2;   // ignored when srgb is true
    bool srgb = false;    // "gamma": "srgb": exact sRGB transfer function
};

struct Scene {
    Camera camera;
    RenderSettings render;
    ShadingModel model;
    std::vector<Light> lights;
    std::vector<Sphere> spheres;
    // Light from all around (issue 24, docs/model.md "Environment light"):
    // absent unless the scene file has "environment"; then it replaces
    // render.background for rays that hit nothing.
    std::optional<Environment> environment;
    std::string sourcePath;  // file it was read from, "<default>" for the embedded one
};

// Limits of the GLSL path (uniform block sizes); the loader rejects more.
constexpr int kMaxSpheres = 64;
// Image size: 16384 a side is the largest texture OpenGL 4.x drivers promise
// (GL_MAX_TEXTURE_SIZE); 2^26 pixels in all (8192x8192) keeps the two RGBA32F
// targets at 2 GiB and the CPU copies at about 3 GiB more.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxPixels = 1LL << 26;
constexpr int kMaxLights = 16;
constexpr int kMaxBounces = 16;

}  // namespace rl
