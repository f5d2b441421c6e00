#include "accuracy/accuracy_support.h"

#include <cctype>

#include "checks/probe_runner.h"
#include "core/error.h"
#include "core/file_io.h"
#include "course/exercise_registry.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "shader/source_assembler.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include <unistd.h>

namespace rl::acc {

using glm::dvec3;

namespace {

// One headless context for the whole test process (each CTest entry is its
// own process), made on first use.
void ensureContext() {
    static std::unique_ptr<GlContext> context = createHeadlessContext(Backend::Auto);
}

std::string programKey(const std::string& kind, const Implementation& impl, const ShaderDefines& defines) {
    std::string key = kind + "|" + impl.dir.string();
    for (const auto& [name, path] : impl.overrides) key += "|" + name + "=" + path.string();
    for (const auto& [name, value] : defines) key += "|" + name + "=" + value;
    return key;
}

std::map<std::string, PictureProgram>& programCache() {
    static std::map<std::string, PictureProgram> cache;
    return cache;
}

}  // namespace

Implementation solutionsWith(const std::map<std::string, std::filesystem::path>& overrides) {
    return Implementation{solutionsDir(), overrides};
}

Implementation alternativesSubmission() {
    static const Implementation submission = [] {
        const std::filesystem::path dir =
            std::filesystem::temp_directory_path() / ("raylab-alternatives-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        for (const ExerciseInfo& e : allExercises()) {
            std::filesystem::path file = solutionsDir() / e.file();
            std::string text = "// my own copy\n" + readRegularFile(file, 1 << 20);
            std::error_code ec;
            std::vector<std::filesystem::path> alternatives;
            for (const auto& f : std::filesystem::directory_iterator(sourceRoot() / e.unitDir() / "alternatives", ec))
                if (f.path().extension() == ".glsl") alternatives.push_back(f.path());
            std::sort(alternatives.begin(), alternatives.end());
            if (!alternatives.empty()) text = readRegularFile(alternatives.front(), 1 << 20);
            writeFileAtomic(dir / e.file(), text);
        }
        return Implementation{dir, {}};
    }();
    return submission;
}

Rendering renderGlsl(const Scene& scene, const Implementation& impl, bool specialise) {
    ensureContext();
    ShaderDefines defines = definesFor(scene, implementationFacts(impl), specialise ? Purpose::Picture : Purpose::Generic);
    auto& cache = programCache();
    std::string key = programKey("raytracer", impl, defines);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, buildPictureProgram(impl, defines)).first;  // with its sky tiles' program
    return renderOnce(it->second, scene, frameFromScene(scene));
}

Rendering renderGlslLive(const Scene& scene, const Implementation& impl) {
    ensureContext();
    // What the live view compiles for its final picture (app/view/view_app.cpp).
    ShaderDefines defines = definesFor(scene, implementationFacts(impl), Purpose::LiveView);
    auto& cache = programCache();
    std::string key = programKey("live", impl, defines);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, PictureProgram{buildRayTracer(impl, defines), std::nullopt}).first;
    return renderOnce(it->second, scene, frameFromScene(scene));
}

const ShaderProgram& probeProgram(int exercise, const Implementation& impl) {
    ensureContext();
    ShaderDefines defines{{"RL_PROBE_EXERCISE", std::to_string(exercise)}};
    auto& cache = programCache();
    std::string key = programKey("probe", impl, defines);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second.program;
    ShaderProgram program(assembleShader("fullscreen.vert", impl, {}), assembleShader("probe.frag", impl, defines));
    return cache.emplace(key, PictureProgram{std::move(program), std::nullopt}).first->second.program;
}

// ---- the double-precision oracle ----------------------------------------------------------

namespace {

// ref::shadeHit() and ref::traceRadiance() with the offset as a parameter;
// every term is the reference's own (brdf_reference.h).
struct OffsetTracer {
    const Scene& scene;
    double relativeOffset;

    dvec3 offsetOrigin(const ref::Hit& hit) const { return hit.p + hit.n * (relativeOffset * hit.magnitude); }

    bool visible(const ref::Hit& hit, dvec3 light) const {
        dvec3 origin = offsetOrigin(hit);
        dvec3 toLight = light - origin;
        double distance = glm::length(toLight);
        if (distance == 0.0) return true;
        return !ref::anyHitBefore(scene, origin, toLight / distance, distance);
    }

    dvec3 shade(const ref::Hit& hit, dvec3 v) const {
        const Material& m = scene.spheres[hit.sphere].material;
        dvec3 radiance(0.0);
        for (const Light& light : scene.lights) {
            dvec3 E = ref::pointLightIrradiance(hit.p, hit.n, light.position, light.color * light.intensity);
            if (E == dvec3(0.0) || !visible(hit, light.position)) continue;
            dvec3 l = glm::normalize(light.position - hit.p);
            radiance += ref::cookTorranceBRDF(hit.n, v, l, m, scene.model) * E;
        }
        return radiance + scene.render.ambient * m.albedo * m.ao;
    }

    dvec3 trace(dvec3 origin, dvec3 dir) const {
        dvec3 radiance(0.0), throughput(1.0);
        for (int bounce = 0; bounce <= scene.render.maxBounces; ++bounce) {
            ref::Hit hit;
            if (!ref::closestHit(scene, origin, dir, hit)) {
                radiance += throughput * scene.render.background;
                break;
            }
            radiance += throughput * shade(hit, -dir);
            const Material& m = scene.spheres[hit.sphere].material;
            double NoV = std::clamp(glm::dot(hit.n, -dir), ref::kMinNoV, 1.0);
            throughput *= ref::F_SchlickRoughness(ref::baseReflectance(m), NoV, m.roughness);
            origin = offsetOrigin(hit);
            dir = glm::reflect(dir, hit.n);
        }
        return radiance;
    }
};

}  // namespace

Rendering renderDoubleWithOffset(const Scene& scene, double relativeOffset) {
    const RenderSettings& settings = scene.render;
    ref::CameraBasis camera = ref::cameraBasis(scene.camera);
    OffsetTracer tracer{scene, relativeOffset};
    int n = int(std::lround(std::sqrt(double(settings.spp))));
    Rendering out;
    out.radiance.width = out.display.width = settings.width;
    out.radiance.height = out.display.height = settings.height;
    out.radiance.rgb.assign(std::size_t(settings.width) * settings.height * 3, 0.0f);
    out.display.rgb.assign(std::size_t(settings.width) * settings.height * 3, 0);
    glm::dvec2 resolution(settings.width, settings.height);
    for (int y = 0; y < settings.height; ++y) {
        int j = settings.height - 1 - y;
        for (int i = 0; i < settings.width; ++i) {
            dvec3 sum(0.0);
            for (int s = 0; s < n * n; ++s) {
                glm::dvec2 sample = glm::dvec2(i, j) + ref::sampleOffset(s, n);
                dvec3 d = ref::cameraRayDirection(sample, resolution, camera.fovYRadians, camera.right, camera.up,
                                                  camera.forward);
                sum += tracer.trace(camera.position, d);
            }
            dvec3 L = sum / double(n * n);
            dvec3 c = ref::displayEncode(L, settings);
            for (int k = 0; k < 3; ++k) {
                out.radiance.at(i, y)[k] = float(L[k]);
                out.display.at(i, y)[k] = quantize8(c[k]);
            }
        }
    }
    return out;
}

// ---- models, scenes, metrics ------------------------------------------------------------------

std::vector<NamedModel> everyModelVariant() {
    std::vector<NamedModel> models(8);
    models[0].name = "beckmann";
    models[0].model.distribution = DistributionModel::Beckmann;
    models[1].name = "smith-ggx";
    models[1].model.geometry = GeometryModel::SmithGGXSeparable;
    models[2].name = "smith-ggx-correlated";
    models[2].model.geometry = GeometryModel::SmithGGXCorrelated;
    models[3].name = "dielectric";
    models[3].model.fresnel = FresnelModel::Dielectric;
    models[4].name = "conductor";
    models[4].model.fresnel = FresnelModel::Conductor;
    models[5].name = "burley";
    models[5].model.diffuse = DiffuseModel::Burley;
    models[6].name = "blinn-phong";
    models[6].model.blinnPhong = true;
    models[7].name = "beckmann+correlated+conductor+burley";
    models[7].model.distribution = DistributionModel::Beckmann;
    models[7].model.geometry = GeometryModel::SmithGGXCorrelated;
    models[7].model.fresnel = FresnelModel::Conductor;
    models[7].model.diffuse = DiffuseModel::Burley;
    return models;
}

std::vector<NamedModel> referenceAndVariants() {
    std::vector<NamedModel> models = everyModelVariant();
    models.insert(models.begin(), NamedModel{"reference", ShadingModel{}});
    return models;
}

std::string modelTestName(const NamedModel& m) {
    std::string name = m.name;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

Scene hardScene(const std::string& file) {
    LoadedScene loaded = loadSceneFile((scenesDir() / "hard" / file).string());
    if (!loaded.warnings.empty()) throw Error(loaded.warnings.front());  // a typo in a hard case is a bug
    return loaded.scene;
}

std::vector<bool> fireflies(const RadianceImage& image, double factor, double floor) {
    auto luminance = [&](int x, int y) {
        const float* p = image.at(x, y);
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];  // Rec. 709 weights of linear rgb
    };
    std::vector<bool> mask(std::size_t(image.width) * image.height, false);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double centre = luminance(x, y);
            bool firefly = !std::isfinite(centre);
            if (!firefly && centre > floor) {
                double brightestNeighbour = 0.0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int nx = x + dx, ny = y + dy;
                        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= image.width || ny >= image.height)
                            continue;
                        double value = luminance(nx, ny);
                        if (std::isfinite(value)) brightestNeighbour = std::max(brightestNeighbour, value);
                    }
                firefly = centre > factor * brightestNeighbour;
            }
            mask[std::size_t(y) * image.width + x] = firefly;
        }
    return mask;
}

long newFireflies(const RadianceImage& got, const RadianceImage& expected) {
    std::vector<bool> a = fireflies(got), b = fireflies(expected);
    long count = 0;
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) count += a[k] && !b[k];
    return count;
}

std::string describeDiff(const ImageDiff& d) {
    char text[256];
    std::snprintf(text, sizeof text, "off %.3f%% mean %.3f p99 %.0f max %d pfmMedianRel %.2g nonFinite %ld",
                  100 * d.offFraction, d.meanLsb, d.p99Lsb, d.maxLsb, d.pfmMedianRel, d.nonFinite);
    return text;
}

// ---- the BRDF probe ---------------------------------------------------------------------------

namespace {

const ShaderProgram& brdfProbeProgram(const ShadingModel& model, const Implementation& impl) {
    ensureContext();
    ShaderDefines defines = modelDefines(model);
    auto& cache = programCache();
    std::string key = programKey("brdf_probe", impl, defines);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second.program;

    // raytracer.glsl with the model's defines, then the probe's main().
    AssembledSource fragment = assembleShader("raytracer.glsl", impl, defines);
    std::filesystem::path probeFile = sourceRoot() / "tests" / "accuracy" / "brdf_probe.glsl";
    std::istringstream in(readSourceFile(probeFile));
    std::string line;
    for (int k = 1; std::getline(in, line); ++k) {
        fragment.append(line, {displayPath(probeFile), k});
    }
    fragment.files.push_back(probeFile);
    AssembledSource vertex = assembleShader("fullscreen.vert", impl, {});
    return cache.emplace(key, PictureProgram{ShaderProgram(vertex, fragment), std::nullopt}).first->second.program;
}

void put(std::array<float, kProbeInputFloats>& in, int at, glm::vec3 value) {
    in[at] = value.x;
    in[at + 1] = value.y;
    in[at + 2] = value.z;
}

}  // namespace

std::vector<glm::vec3> runBrdfProbe(BrdfProbe probe, const std::vector<BrdfCase>& cases, const ShadingModel& model,
                                    const Implementation& impl) {
    const ShaderProgram& program = brdfProbeProgram(model, impl);
    std::vector<glm::vec3> results;
    results.reserve(cases.size());
    // runProbe() lays the cases out 256 per row; batches keep its input
    // texture small (96 bytes per case).
    constexpr std::size_t kBatch = 65536;
    for (std::size_t first = 0; first < cases.size(); first += kBatch) {
        ProbeSpec spec("brdf_probe", "brdf_probe(n, v, l, material)", 3);
        spec.programFunction = int(probe);
        for (std::size_t k = first; k < std::min(cases.size(), first + kBatch); ++k) {
            const BrdfCase& c = cases[k];
            ProbeCase pc;
            put(pc.in, 0, c.n);
            pc.in[3] = c.roughness;
            put(pc.in, 4, c.v);
            pc.in[7] = c.metallic;
            put(pc.in, 8, c.l);
            put(pc.in, 12, c.albedo);
            put(pc.in, 16, c.edgeTint);
            spec.cases.push_back(pc);
        }
        for (const auto& r : runProbe(program, spec, nullptr)) results.emplace_back(r[0], r[1], r[2]);
    }
    return results;
}

dvec3 expectedBrdf(BrdfProbe probe, const BrdfCase& c, const ShadingModel& model) {
    Material m;
    m.albedo = dvec3(c.albedo);
    m.roughness = c.roughness;
    m.metallic = c.metallic;
    m.edgeTint = dvec3(c.edgeTint);
    // The unit vectors the float inputs round: the GPU gets vectors whose
    // length is 1 only to ~1e-7, which the double formulas must not amplify
    // (NoH^s at s = 4.9e5 would turn it into 6%).
    dvec3 n = glm::normalize(dvec3(c.n)), v = glm::normalize(dvec3(c.v)), l = glm::normalize(dvec3(c.l));
    switch (probe) {
        case BrdfProbe::Brdf: return ref::cookTorranceBRDF(n, v, l, m, model);
        case BrdfProbe::Specular: return ref::specularBRDF(n, v, l, m, model);
        case BrdfProbe::Diffuse: return ref::diffuseBRDF(n, v, l, m, model);
        case BrdfProbe::D: {
            double alpha = ref::ggxAlpha(m.roughness);
            if (model.blinnPhong) return dvec3(ref::Fr_BlinnPhong(glm::dot(n, l), ref::shininessFromAlpha(alpha)));
            if (model.distribution == DistributionModel::Beckmann) return dvec3(ref::D_Beckmann(n, l, alpha));
            return dvec3(ref::D_GGX(n, l, alpha));
        }
        case BrdfProbe::F: {
            dvec3 F0 = ref::baseReflectance(m);
            double VoH = glm::dot(v, l);
            if (model.fresnel == FresnelModel::Dielectric) return ref::F_Dielectric(F0, VoH);
            if (model.fresnel == FresnelModel::Conductor) return ref::F_Conductor(F0, m.edgeTint, VoH);
            return ref::F_Schlick(F0, VoH);
        }
    }
    return dvec3(0.0);
}

}  // namespace rl::acc
