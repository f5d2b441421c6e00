#include "render/pixel_debugger.h"

#include "core/error.h"
#include "core/float_range.h"
#include "course/exercise_registry.h"
#include "gl/gl_api.h"
#include "reference/brdf_reference.h"
#include "reference/cpu_reference.h"
#include "reference/pixel_breakdown.h"
#include "render/define_table.h"
#include "render/environment_resources.h"
#include "render/implementation_facts.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

namespace rl {
namespace {

using glm::dvec3;
using K = PixelValueKind;

// Fragments of the read-back: more than any path records (2 + per hit
// 4 + 15 per light + 2, + a weight per bounce + 2: 3 lights and 8 bounces
// make 452). A path that records more is cut here, said in the table.
constexpr int kSlots = 1024;

// The exercise (by a function it implements) and the function's words.
struct Source {
    const char* function;  // as the unit declares it, the value's expression
    const char* implementer;  // the function the registry knows (exerciseOfFunction)
};
Source sourceOf(K kind, int bounce) {
    switch (kind) {
        case K::SampleOffset: return {"sampleOffset(0, n)", "sampleOffset"};
        case K::CameraRay: return {"cameraRayDirection(pixel centre)", "cameraRayDirection"};
        case K::Ray:
            return bounce == 0 ? Source{"cameraRayDirection(pixel centre)", "cameraRayDirection"}
                               : Source{"traceRay: the bounce's direction", "traceRay"};
        case K::Hit: case K::Point: case K::Normal: case K::Miss:
            return {bounce == 0 ? "closestHit via intersectSphere" : "closestHit via intersectSphere (from traceRay's origin)",
                    "intersectSphere"};
        case K::LightDir: return {"framework: l", ""};
        case K::Half: return {"framework: h = normalize(l + v)", ""};
        case K::Angles: return {"framework: n.l, n.v (clamped), v.h", ""};
        case K::Irradiance: return {"pointLightIrradiance(p, n, light)", "pointLightIrradiance"};
        case K::Lambert: return {"Fd_Lambert(albedo)", "Fd_Lambert"};
        case K::Visibility: return {"lightVisibility(hit, light)", "lightVisibility"};
        case K::D: return {"D_GGX(n, h, ggxAlpha(r))", "D_GGX"};
        case K::G: return {"G_SchlickGGX(NoV, NoL, r)", "G_SchlickGGX"};
        case K::F: return {"F_Schlick(F0, v.h)", "F_Schlick"};
        case K::Alpha: return {"ggxAlpha(r)", "ggxAlpha"};
        case K::F0: return {"baseReflectance(m)", "baseReflectance"};
        case K::Diffuse: return {"diffuseBRDF * E", "diffuseBRDF"};
        case K::Specular: return {"specularBRDF * E", "specularBRDF"};
        case K::Brdf: return {"cookTorranceBRDF * E", "cookTorranceBRDF"};
        case K::Shaded: return {"framework: shadeHit (lights + ambient + environment)", ""};
        case K::EnvIrradiance: return {"shIrradiance(n in the environment's frame) * intensity", "shIrradiance"};
        case K::EnvLevel: return {"prefilteredLevel(roughness, levels)", "prefilteredLevel"};
        case K::EnvPrefiltered: return {"framework: prefilteredRadiance(r, level) * intensity", ""};
        case K::EnvScaleBias: return {"framework: splitSumLookup(n.v, roughness)", ""};
        case K::EnvVisibility: return {"sphereFormFactor(p, n, centre, radius), summed over the other spheres", "sphereFormFactor"};
        case K::EnvLight: return {"environmentShading(irradiance, prefiltered, scaleBias, m)", "environmentShading"};
        case K::Weight: return {"traceRay: the bounce's weight", "traceRay"};
        case K::Radiance: return {"traceRay: radiance", "traceRay"};
        case K::Display: return {"displayEncode(radiance), clamped", "displayEncode"};
    }
    return {"", ""};
}

int componentsOf(K kind) {
    switch (kind) {
        case K::SampleOffset: case K::Hit: return 2;
        case K::Visibility: case K::D: case K::G: case K::Alpha: case K::EnvLevel: case K::EnvVisibility: return 1;
        case K::EnvScaleBias: return 2;
        default: return 3;
    }
}

const char* shortName(K kind) {
    switch (kind) {
        case K::SampleOffset: return "sample offset, n";
        case K::CameraRay: return "camera ray";
        case K::Ray: return "ray direction";
        case K::Hit: return "t, sphere";
        case K::Point: return "p";
        case K::Normal: return "n";
        case K::Miss: return "no hit: background";
        case K::LightDir: return "l";
        case K::Half: return "h";
        case K::Angles: return "n.l, n.v, v.h";
        case K::Irradiance: return "E";
        case K::Lambert: return "Lambert";
        case K::Visibility: return "visibility";
        case K::D: return "D";
        case K::G: return "G";
        case K::F: return "F";
        case K::Alpha: return "alpha";
        case K::F0: return "F0";
        case K::Diffuse: return "diffuse";
        case K::Specular: return "specular";
        case K::Brdf: return "BRDF * E";
        case K::Shaded: return "shaded";
        case K::EnvIrradiance: return "environment irradiance";
        case K::EnvLevel: return "prefiltered level";
        case K::EnvPrefiltered: return "prefiltered radiance";
        case K::EnvScaleBias: return "split-sum scale, bias";
        case K::EnvVisibility: return "spheres' form factors";
        case K::EnvLight: return "environment light";
        case K::Weight: return "weight";
        case K::Radiance: return "radiance";
        case K::Display: return "display";
    }
    return "?";
}

// float32 against double, per component: |gl - ref| <= abs + rel |ref|.
// - Values from the material and the settings alone (the sample offset,
//   Lambert, alpha, F0, the background, the display step's inputs are
//   exact floats): a few float32 operations, each within 2^-24 relative;
//   1e-5 relative is 160 such roundings.
// - Values along the ray (t, p, n, angles, E, D, G, F, the BRDF terms, the
//   weights, the radiance): their inputs already carry float32's error of
//   the hit point (error_bounds.glsl: a few 1e-7 of the scene's size),
//   which a function multiplies by its condition number. 1e-3 relative
//   (and 1e-4 absolute for unit vectors and cosines) leaves a factor of
//   more than 1000 over those inputs; the largest ratio error/tolerance
//   over every pixel of the default scene with the solutions is quoted in
//   docs/lecture.md ("Ask a pixel"). Every mutant of the course moves its
//   value by far more (a factor pi, a missing 1/4, a swapped root).
// - Visibility and the sphere index: exact.
std::pair<double, double> tolerance(K kind) {
    switch (kind) {
        case K::SampleOffset: case K::Lambert: case K::Alpha: case K::F0: case K::Miss: case K::EnvLevel:
            return {1e-6, 1e-5};
        case K::Visibility: return {0.5, 0.0};
        // The spheres' form factors: a few spheres' sphereFormFactor() summed,
        // each within its probes' tolerance (at most 1.3e-4: the drivers' acos
        // and atan, course/12-sky-shadows/probes.cpp) at the hit's float32
        // p and n; 2e-3 absolute for the sum. A changed pixel of a mistake
        // moves it by 1e-2 and more.
        case K::EnvVisibility: return {2e-3, 1e-3};
        case K::CameraRay: case K::Ray: case K::Normal: case K::LightDir: case K::Half: case K::Angles:
            return {1e-4, 1e-3};
        case K::Display: return {1e-4, 1e-3};  // a fortieth of an 8-bit step
        default: return {1e-6, 1e-3};
    }
}

// Sets v.toleranceUsed; true when every component is within tolerance.
bool within(PixelValue& v) {
    if (!v.reference) return false;
    const auto [abs, rel] = tolerance(v.kind);
    v.toleranceUsed = 0;
    for (int c = 0; c < v.components; ++c) {
        const double g = v.gl[c], r = (*v.reference)[c];
        if (!std::isfinite(g)) return false;
        if (v.kind == K::Hit && c == 1) {
            if (g != r) return false;  // another sphere
            continue;
        }
        v.toleranceUsed = std::max(v.toleranceUsed, std::abs(g - r) / (abs + v.extraTolerance + rel * std::abs(r)));
    }
    return v.toleranceUsed <= 1.0;
}

using Key = std::tuple<int, int, int>;  // kind, bounce, light

// The CPU reference's value of every key its path has.
// The extra absolute tolerance of the values made from a steep environment
// lookup: its spread, carried through the split sum (times F0 scale + bias),
// into the hit's shaded light and, by the throughput, into the radiance.
std::map<Key, double> lookupSpreads(const ref::PixelTerms& t) {
    std::map<Key, double> out;
    double radiance = 0;
    for (const ref::BounceTerms& b : t.chain) {
        if (!b.environment) continue;
        const ref::EnvironmentTerms& e = *b.environment;
        const double spread = std::max({e.prefilteredSpread.x, e.prefilteredSpread.y, e.prefilteredSpread.z});
        const dvec3 F0 = ref::baseReflectance(b.material);
        const double factor = std::max({F0.x, F0.y, F0.z}) * e.scaleBias.x + e.scaleBias.y;
        out[{int(K::EnvPrefiltered), b.depth, -1}] = spread;
        out[{int(K::EnvLight), b.depth, -1}] = spread * factor;
        out[{int(K::Shaded), b.depth, -1}] = spread * factor;
        radiance += spread * factor * std::max({b.throughput.x, b.throughput.y, b.throughput.z});
    }
    out[{int(K::Radiance), 0, -1}] = radiance;
    return out;
}

std::map<Key, dvec3> referenceValues(const Scene& scene, const ref::PixelTerms& t, int maxWeights) {
    std::map<Key, dvec3> out;
    const int n = std::max(1, int(std::sqrt(double(scene.render.spp)) + 0.5));
    const glm::dvec2 offset = ref::sampleOffset(0, n);
    out[{int(K::SampleOffset), 0, -1}] = dvec3(offset, n);
    if (!t.chain.empty()) out[{int(K::CameraRay), 0, -1}] = t.chain.front().dir;
    for (const ref::BounceTerms& b : t.chain) {
        const int d = b.depth;
        out[{int(K::Ray), d, -1}] = b.dir;  // a miss too: a program that hits there is compared on its ray first
        if (!b.hit) {
            out[{int(K::Miss), d, -1}] = scene.render.background;
            continue;
        }
        const Material& m = b.material;
        out[{int(K::Hit), d, -1}] = dvec3(b.t, b.sphere, 0);
        out[{int(K::Point), d, -1}] = b.p;
        out[{int(K::Normal), d, -1}] = b.n;
        const double NoV = std::clamp(glm::dot(b.n, b.v), ref::kMinNoV, 1.0);
        for (const ref::LightTerms& l : b.lights) {
            const int i = l.light;
            const dvec3 E = l.E;
            const dvec3 lit = l.facesAway || l.shadowed ? dvec3(0.0) : E;
            out[{int(K::LightDir), d, i}] = l.l;
            out[{int(K::Half), d, i}] = l.h;
            out[{int(K::Angles), d, i}] = dvec3(l.NoL, NoV, l.VoH);
            out[{int(K::Irradiance), d, i}] = E;
            out[{int(K::Lambert), d, i}] = ref::Fd_Lambert(m.albedo);
            out[{int(K::Visibility), d, i}] = dvec3(l.facesAway ? -1.0 : l.shadowed ? 0.0 : 1.0, 0, 0);
            out[{int(K::D), d, i}] = dvec3(ref::D_GGX(b.n, l.h, ref::ggxAlpha(m.roughness)), 0, 0);
            out[{int(K::G), d, i}] = dvec3(ref::G_SchlickGGX(NoV, l.NoL, m.roughness), 0, 0);
            out[{int(K::F), d, i}] = ref::F_Schlick(ref::baseReflectance(m), l.VoH);
            out[{int(K::Alpha), d, i}] = dvec3(ref::ggxAlpha(m.roughness), 0, 0);
            out[{int(K::F0), d, i}] = ref::baseReflectance(m);
            out[{int(K::Diffuse), d, i}] = ref::diffuseBRDF(b.n, b.v, l.l, m) * lit;
            out[{int(K::Specular), d, i}] = ref::specularBRDF(b.n, b.v, l.l, m) * lit;
            out[{int(K::Brdf), d, i}] = ref::cookTorranceBRDF(b.n, b.v, l.l, m) * lit;
        }
        if (b.environment) {
            const ref::EnvironmentTerms& e = *b.environment;
            out[{int(K::EnvIrradiance), d, -1}] = e.irradiance;
            out[{int(K::EnvLevel), d, -1}] = dvec3(e.level, 0, 0);
            out[{int(K::EnvPrefiltered), d, -1}] = e.prefiltered;
            out[{int(K::EnvScaleBias), d, -1}] = dvec3(e.scaleBias, 0);
            out[{int(K::EnvVisibility), d, -1}] = dvec3(e.formFactors, 0, 0);
            out[{int(K::EnvLight), d, -1}] = e.light;
        }
        out[{int(K::Shaded), d, -1}] = b.shaded;
    }
    for (int k = 0; k < maxWeights; ++k)
        out[{int(K::Weight), k, -1}] = k < int(t.chain.size()) ? t.chain[std::size_t(k)].throughput : dvec3(0.0);
    out[{int(K::Radiance), 0, -1}] = t.radiance;
    out[{int(K::Display), 0, -1}] = glm::clamp(ref::displayEncode(t.radiance, scene.render), 0.0, 1.0);
    return out;
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}
std::string valueText(const dvec3& v, int components) {
    if (components == 1) return num(v.x);
    std::string s = "(" + num(v.x) + ", " + num(v.y);
    if (components == 3) s += ", " + num(v.z);
    return s + ")";
}

}  // namespace

std::string PixelValue::name() const {
    std::string s;
    if (kind != K::SampleOffset && kind != K::CameraRay && kind != K::Radiance && kind != K::Display)
        s = bounce == 0 ? "primary hit" : "bounce " + std::to_string(bounce);
    if (kind == K::Weight) s = "bounce " + std::to_string(bounce);
    if (light >= 0) s += ", lights[" + std::to_string(light) + "]";
    return (s.empty() ? "" : s + ": ") + shortName(kind);
}

ShaderProgram buildPixelDebugProgram(const Implementation& impl, const Scene& scene) {
    // The define table's pixel-debug purpose: the generic program, recording,
    // without the environment's occlusion (exercise 12's form factors are
    // recorded on their own row, pixel_debug.glsl; docs/decisions.md).
    const ShaderDefines defines = definesFor(scene, implementationFacts(impl), Purpose::PixelDebug);
    return ShaderProgram(assembleShader("fullscreen.vert", impl, {}), assembleShader("pixel_debug.frag", impl, defines));
}

std::vector<std::array<float, 4>> recordPixelValues(const ShaderProgram& program, const Scene& scene,
                                                    const FrameSettings& frame, int i, int j) {
    GLuint target = 0, framebuffer = 0, vertexArray = 0;
    GLint previousFramebuffer = 0, previousViewport[4] = {0, 0, 0, 0};
    gl::GetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFramebuffer);
    gl::GetIntegerv(GL_VIEWPORT, previousViewport);
    gl::GenTextures(1, &target);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, target);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kSlots, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::GenFramebuffers(1, &framebuffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    const GLenum buffers[1] = {GL_COLOR_ATTACHMENT0};
    gl::DrawBuffers(1, buffers);

    // The environment's tables, as GlRenderer binds them for the picture
    // (units 1-4; unit 0 is the target's here): without them the program
    // would see an environment of intensity 0.
    std::optional<EnvironmentTextures> environment;
    if (scene.environment) {
        environment.emplace(environmentResources(*scene.environment));
        environment->bind(program, *scene.environment);
        gl::ActiveTexture(GL_TEXTURE0);
    }
    setFrameUniforms(program, scene, frame);  // the picture's uniforms, at the picture's size
    gl::Uniform2f(program.uniform("u_debugPixel"), float(i), float(j));
    SceneUniformBlock block;
    block.upload(scene, framePosition(frame), sceneAnchor(scene));
    block.bind(program);
    gl::Viewport(0, 0, kSlots, 1);
    gl::GenVertexArrays(1, &vertexArray);
    gl::BindVertexArray(vertexArray);
    gl::Disable(GL_SCISSOR_TEST);  // as every draw leaves it (GlRenderer's sky tiles disable it after theirs)
    gl::DrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<std::array<float, 4>> values(kSlots);
    gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, kSlots, 1, GL_RGBA, GL_FLOAT, values.data());
    const GLenum error = gl::GetError();
    gl::DeleteVertexArrays(1, &vertexArray);
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteTextures(1, &target);
    gl::UseProgram(0);  // the caller's program is not left current (its own deletion unbinds it too: shader/program.cpp)
    gl::BindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    gl::Viewport(previousViewport[0], previousViewport[1], previousViewport[2], previousViewport[3]);
    if (error != GL_NO_ERROR) throw Error("OpenGL error while asking a pixel: " + gl::errorName(error));
    return values;
}

PixelDebug debugPixel(const ShaderProgram& program, const Scene& scene, const Camera& camera, int width, int height,
                      int i, int j, const std::string& implementation) {
    std::shared_ptr<const EnvironmentResources> resources;
    ref::EnvironmentTables tables;
    if (scene.environment) {
        resources = environmentResources(*scene.environment);  // the picture's tables (cached)
        tables = {&resources->sh, &resources->levels, &resources->table, resources->settings.tableSize,
                  resources->sun.present, resources->sun.direction, resources->sun.power, resources->sun.angularRadius};
    }
    const ref::PixelTerms terms =
        ref::explainPixel(scene, camera, width, height, i, j, resources ? &tables : nullptr);  // throws outside
    Scene seen = scene;
    seen.camera = camera;
    FrameSettings frame = frameFromScene(seen);
    frame.width = width;
    frame.height = height;
    const std::vector<std::array<float, 4>> raw = recordPixelValues(program, seen, frame, i, j);

    PixelDebug out;
    out.i = i;
    out.j = j;
    out.width = width;
    out.height = height;
    out.implementation = implementation;
    const dvec3 anchor = sceneAnchor(seen);
    const double unit = shaderUnits(seen, framePosition(frame)).unit;
    const std::map<Key, dvec3> expected = referenceValues(seen, terms, seen.render.maxBounces + 1);
    const std::map<Key, double> spreads = lookupSpreads(terms);
    for (const auto& texel : raw) {
        if (texel[3] < 0) {
            out.loopRanAway = true;
            break;
        }
        const int key = int(std::lround(texel[3]));
        if (key <= 0) break;
        PixelValue v;
        v.kind = K(key % 100);
        v.bounce = key / 100 % 100;
        v.light = key / 10000 - 1;
        v.gl = dvec3(texel[0], texel[1], texel[2]);
        if (v.kind == K::Point) v.gl = anchor + unit * v.gl;
        if (v.kind == K::Hit) v.gl.x *= unit;
        v.components = componentsOf(v.kind);
        if (auto it = expected.find({int(v.kind), v.bounce, v.light}); it != expected.end()) v.reference = it->second;
        if (auto it = spreads.find({int(v.kind), v.bounce, v.light}); it != spreads.end()) v.extraTolerance = it->second;
        Source source = sourceOf(v.kind, v.bounce);
        if (!v.reference) {
            // A value the model's path does not have: past the path's last
            // bounce, traceRay went on; where the model's ray leaves the
            // scene (or, at the camera ray, hits something else), the hit is
            // the intersection's.
            const bool modelBounce =
                expected.count({int(K::Miss), v.bounce, -1}) > 0 || expected.count({int(K::Hit), v.bounce, -1}) > 0;
            if (!modelBounce && v.bounce > 0)
                source = {"traceRay: a bounce the model's path does not have", "traceRay"};
            else if (v.kind == K::Hit || v.kind == K::Point || v.kind == K::Normal || v.kind == K::Miss)
                source = sourceOf(K::Hit, v.bounce);
        }
        v.function = source.function;
        if (*source.implementer)
            if (const ExerciseInfo* unit = exerciseOfFunction(source.implementer); unit && unit->inCourse)
                v.exercise = unit->number;
        v.differs = !within(v);
        if (v.differs && out.firstDifference < 0) out.firstDifference = int(out.values.size());
        out.values.push_back(std::move(v));
    }
    // The picture's pixel is the centre ray's display colour only where the
    // samples sit where the model puts them: a wrong sample offset moves the
    // picture's rays off the centre this table traces.
    // Likewise the spheres' form factors (exercise 12): this table's program
    // leaves the occlusion out (buildPixelDebugProgram), the picture's does
    // not, so where they differ the picture's pixel differs too.
    bool samplesAgree = true, formFactorsAgree = true;
    for (const PixelValue& v : out.values) {
        if (v.kind == K::SampleOffset) samplesAgree = !v.differs;
        if (v.kind == K::EnvVisibility && v.differs) formFactorsAgree = false;
        if (v.kind == K::Display)
            out.pixelAgrees = !v.differs && samplesAgree && formFactorsAgree && !out.loopRanAway;
    }
    // A value the reference's path has and the program's does not (a path
    // that stops early): missing on screen, the program's side empty.
    if (out.firstDifference < 0 && !out.loopRanAway) {
        for (const auto& entry : expected) {
            const Key& key = entry.first;  // not a structured binding: C++17 lambdas cannot capture those (clang)
            const dvec3& value = entry.second;
            const bool present = std::any_of(out.values.begin(), out.values.end(), [&key](const PixelValue& v) {
                return std::tuple(int(v.kind), v.bounce, v.light) == key;
            });
            if (present) continue;
            // The program records a ray's direction at its hits only: a
            // ray the model sees leave the scene has its miss compared instead.
            if (std::get<0>(key) == int(K::Ray) && expected.count({int(K::Miss), std::get<1>(key), -1})) continue;
            PixelValue v;
            v.kind = K(std::get<0>(key));
            v.bounce = std::get<1>(key);
            v.light = std::get<2>(key);
            v.gl = dvec3(std::nan(""));
            v.reference = value;
            v.components = componentsOf(v.kind);
            const Source source = sourceOf(v.kind, v.bounce);
            v.function = source.function;
            if (v.bounce > 0) v.function = "traceRay: this bounce was never traced";
            if (const ExerciseInfo* unit = exerciseOfFunction(v.bounce > 0 ? "traceRay" : source.implementer);
                unit && unit->inCourse)
                v.exercise = unit->number;
            v.differs = true;
            out.firstDifference = int(out.values.size());
            out.values.push_back(std::move(v));
            break;
        }
    }
    return out;
}

namespace {

std::string exerciseName(const PixelValue& f) {
    return f.exercise > 0 ? findExercise(std::to_string(f.exercise)).id : std::string("the framework");
}
std::string programValue(const PixelValue& f) {
    return std::isnan(f.gl.x) ? std::string("not computed") : valueText(f.gl, f.components);
}
std::string modelValue(const PixelValue& f) {
    return f.reference ? valueText(*f.reference, f.components) : std::string("nothing");
}

}  // namespace

std::vector<std::string> askedFunctions() {
    std::vector<std::string> out;
    for (int k = 1; k < 100; ++k)
        for (int bounce : {0, 1}) {
            const Source s = sourceOf(K(k), bounce);
            if (*s.implementer && std::find(out.begin(), out.end(), s.implementer) == out.end())
                out.push_back(s.implementer);
        }
    return out;
}

std::string pixelDebugVerdict(const PixelDebug& d) {
    if (d.loopRanAway) return "a loop of an exercise file ran past its bound at this pixel: the values stop there";
    const PixelValue* f = d.first();
    if (!f) return "this pixel agrees with the model: every value within float32 tolerance of the CPU reference";
    std::string line = f->name() + " = " + f->function + " in " + exerciseName(*f);
    if (f->exercise > 0) line += " (" + findExercise(std::to_string(f->exercise)).handout() + ")";
    line += ": " + programValue(*f) + " here, " + modelValue(*f) + " in the reference";
    if (d.pixelAgrees)
        return "this pixel agrees with the model (its display colour within tolerance); an intermediate value "
               "differs, not affecting this pixel: " + line;
    return "first difference: " + line;
}

std::vector<std::string> pixelDebugLabel(const PixelDebug& d) {
    if (d.loopRanAway) return {"a loop ran past its bound here"};
    const PixelValue* f = d.first();
    if (!f) return {"agrees with the model"};
    if (d.pixelAgrees) return {"agrees with the model", "(" + f->name() + " differs, not affecting this pixel)"};
    // Short: the quantity (the primary hit unsaid), the function, 5 digits.
    std::string where = f->function.substr(0, f->function.find('('));
    if (where.rfind("framework: ", 0) == 0) where = where.substr(11);
    std::string name = f->name();
    for (const char* primary : {"primary hit: ", "primary hit, "})
        if (name.rfind(primary, 0) == 0) name = name.substr(std::string(primary).size());
    auto brief = [f](const dvec3& v) {
        char text[96];
        if (f->components == 1) std::snprintf(text, sizeof text, "%.5g", v.x);
        else if (f->components == 2) std::snprintf(text, sizeof text, "(%.5g, %.5g)", v.x, v.y);
        else std::snprintf(text, sizeof text, "(%.5g, %.5g, %.5g)", v.x, v.y, v.z);
        return std::string(text);
    };
    return {name + ": " + where + " in " + exerciseName(*f),
            "here  " + (std::isnan(f->gl.x) ? std::string("not computed") : brief(f->gl)),
            "model " + (f->reference ? brief(*f->reference) : std::string("nothing"))};
}

std::string formatPixelDebug(const PixelDebug& d) {
    std::ostringstream s;
    // The answer first: a pixel whose final value agrees says so before any
    // difference in between is listed.
    s << pixelDebugVerdict(d) << "\n";
    s << "pixel (" << d.i << ", " << d.height - 1 - d.j << ") from the top left of " << d.width << "x" << d.height
      << ", its centre ray: " << (d.implementation.empty() ? "this program" : d.implementation)
      << " (float32, on the GPU) | CPU reference (double)\n";
    if (d.pixelAgrees && d.first())
        s << "(\"~\": differs from the model but does not reach this pixel's display colour)\n";
    for (std::size_t k = 0; k < d.values.size(); ++k) {
        const PixelValue& v = d.values[k];
        const char* mark = !v.differs ? "  " : d.pixelAgrees ? " ~" : int(k) == d.firstDifference ? ">>" : " !";
        char ex[16] = "  ";
        if (v.exercise > 0) std::snprintf(ex, sizeof ex, "%02d", v.exercise);
        s << mark << " " << ex << " " << v.name() << ": "
          << (std::isnan(v.gl.x) ? std::string("-") : valueText(v.gl, v.components)) << " | "
          << (v.reference ? valueText(*v.reference, v.components) : std::string("-")) << "\n";
    }
    if (!d.hint.empty()) s << d.hint << "\n";
    return s.str();
}

}  // namespace rl
