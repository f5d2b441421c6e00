#include "render/scene_uniforms.h"

#include "core/error.h"
#include "core/float_range.h"
#include "core/light_surface.h"
#include "core/message.h"
#include "render/bounce_cutoff.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rl {

glm::dmat4 cameraToWorld(const Camera& c) {
    glm::dvec3 f = glm::normalize(c.target - c.position);
    glm::dvec3 r = glm::normalize(glm::cross(f, c.up));
    glm::dvec3 u = glm::cross(r, f);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(r, 0.0);
    m[1] = glm::dvec4(u, 0.0);
    m[2] = glm::dvec4(-f, 0.0);
    m[3] = glm::dvec4(c.position, 1.0);
    return m;
}

namespace {
// std140 layout of SceneBlock in shaders/scene.glsl: six vec4 arrays, the camera, two more arrays.
struct SceneBlockData {
    glm::vec4 sphereGeometry[kMaxSpheres];
    glm::vec4 sphereSurface[kMaxSpheres];
    glm::vec4 sphereExtra[kMaxSpheres];
    glm::vec4 sphereEdgeTint[kMaxSpheres];
    glm::vec4 lightPosition[kMaxLights];
    glm::vec4 lightIntensity[kMaxLights];
    glm::vec4 cameraFromAnchor;
    glm::vec4 sphereFromCamera[kMaxSpheres];
    glm::vec4 lightSurface[kMaxLights];
};
constexpr GLuint kSceneBlockBinding = 0;
}  // namespace

SceneUniformBlock::SceneUniformBlock() {
    gl::GenBuffers(1, &buffer_);
    gl::BindBuffer(GL_UNIFORM_BUFFER, buffer_);
    gl::BufferData(GL_UNIFORM_BUFFER, sizeof(SceneBlockData), nullptr, GL_DYNAMIC_DRAW);
}

SceneUniformBlock::~SceneUniformBlock() {
    if (buffer_) gl::DeleteBuffers(1, &buffer_);
}

CameraSphere cameraSphere(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& anchor, double unit) {
    constexpr double u = kFloatUnitRoundoff;
    // C from the world's numbers in long double (x87: 11 more bits than
    // double): a camera put on a sphere's surface is a rounding of double off
    // it, and |e - c| - r, rounded in double, can take the wrong side; the
    // differences e - c of doubles are exact there, and the sign of C is the
    // one the true picture has.
    using Real = long double;
    const Real fx = Real(eye.x) - Real(sphere.center.x), fy = Real(eye.y) - Real(sphere.center.y),
               fz = Real(eye.z) - Real(sphere.center.z), r = Real(sphere.radius);
    const Real distance = std::sqrt(fx * fx + fy * fy + fz * fz);
    CameraSphere out;
    out.C = double((distance - r) * (distance + r) / (Real(unit) * Real(unit)));
    // exerciseCError() of error_bounds.glsl, on the numbers the shader holds:
    // 4 u (2 |f|.(|e| + |c|) + 4 (|f|^2 + r^2)).
    const glm::dvec3 eyeFromAnchor = (eye - anchor) / unit, c = (sphere.center - anchor) / unit, f = eyeFromAnchor - c;
    const double rs = sphere.radius / unit, fs = glm::length(f);
    glm::dvec3 af = glm::abs(f), spread = glm::abs(eyeFromAnchor) + glm::abs(c);
    double exerciseError = 4.0 * u * (2.0 * glm::dot(af, spread) + 4.0 * (fs * fs + rs * rs));
    // Beyond float32's range C is no use to the shader: a camera that far is
    // clearly outside (or inside) and the exercise tells it.
    out.hostDecides = std::abs(out.C) < exerciseError && std::abs(out.C) < 1e37;
    return out;
}

LightOnSurface lightOnSurface(const Scene& scene, std::size_t k, const glm::dvec3& anchor, double unit) {
    constexpr double u = kFloatUnitRoundoff;
    const glm::dvec3 light = scene.lights.at(k).position;
    LightOnSurface out;
    double nearest = INFINITY;
    for (std::size_t i = 0; i < scene.spheres.size() && i < std::size_t(kMaxSpheres); ++i) {
        const Sphere& s = scene.spheres[i];
        // float32 holds the light and the centre relative to the anchor, each
        // to u of its size, and the shader's |o - c|^2 - r^2 near the light
        // rounds by about 3 u (|o - c|^2 + r^2), about 6 u r^2: in height,
        // 3 u r. 4 u of the sizes covers both; more would take lights that
        // float32 does place (0.08 above a ground of radius 1e5, whose
        // surface it resolves to 0.02 there) from the exercise's shadow test.
        glm::dvec3 l = (light - anchor) / unit, c = (s.center - anchor) / unit;
        double reach = 4.0 * u * (glm::length(l) + glm::length(c) + s.radius / unit);
        double distance = std::abs(surfaceDistance(light, s)) / unit;
        if (distance <= reach && distance < nearest) {
            nearest = distance;
            out.sphere = int(i);
            out.side = lightSurfaceSide(light, s);
        }
    }
    return out;
}

ShaderScene shaderScene(const Scene& scene, const glm::dvec3& eye, const glm::dvec3& anchor) {
    // Relative to the anchor, in double until the last step (docs/numerics.md):
    // a scene far from the world origin, or a camera far from the scene, then
    // loses in float32 only the rounding of the scene's own size.
    ShaderUnits units = shaderUnits(scene, eye);
    ShaderScene out;
    const double unit = units.unit, area = unit * unit;  // powers of two: exact
    out.unit = unit;
    const std::size_t spheres = std::min(scene.spheres.size(), std::size_t(kMaxSpheres));
    const std::size_t lights = std::min(scene.lights.size(), std::size_t(kMaxLights));
    for (std::size_t i = 0; i < spheres; ++i) {
        const Sphere& s = scene.spheres[i];
        glm::dvec3 centre = (s.center - anchor) / unit;
        double radius = s.radius / unit;
        // |c|^2 - r^2 of every ray from the anchor, as (|c| - r)(|c| + r): no
        // cancellation near a huge sphere (error_bounds.glsl, refineRoot).
        double distance = glm::length(centre);
        double anchorC = (distance - radius) * (distance + radius);
        out.sphereGeometry.push_back(glm::vec4(shaderPosition(s.center, anchor, unit), float(radius)));
        out.sphereSurface.push_back(glm::vec4(glm::vec3(s.material.albedo), float(s.material.roughness)));
        out.sphereExtra.push_back(glm::vec4(float(s.material.metallic), float(s.material.ao), float(anchorC),
                                            refinesRoots(scene, i) ? 1.0f : 0.0f));
        out.sphereEdgeTint.push_back(glm::vec4(glm::vec3(s.material.edgeTint), 0.0f));
        // The camera's relation to the sphere, for this camera (the live view
        // uploads the block again whenever its camera moves): C = |e - c|^2 -
        // r^2 in double, and whether the exercise's float32 can tell its sign
        // (error_bounds.glsl, exerciseCError, with the same margins).
        CameraSphere relation = cameraSphere(s, eye, anchor, unit);
        out.sphereFromCamera.push_back(glm::vec4(float(relation.C), relation.hostDecides ? 1.0f : 0.0f, 0.0f, 0.0f));
    }
    for (std::size_t k = 0; k < lights; ++k) {
        const Light& l = scene.lights[k];
        glm::dvec3 intensity = units.lightsTooClose ? glm::dvec3(0.0) : l.color * l.intensity / area;
        out.lightPosition.push_back(glm::vec4(shaderPosition(l.position, anchor, unit), 1.0f));
        out.lightIntensity.push_back(glm::vec4(glm::vec3(intensity), 0.0f));
        // Its nearness to a sphere's surface, within what float32 can
        // resolve around it, and its side from double (docs/model.md).
        LightOnSurface near = lightOnSurface(scene, k, anchor, unit);
        out.lightSurface.push_back(glm::vec4(float(near.sphere), float(near.side), 0.0f, 0.0f));
    }
    out.cameraFromAnchor = glm::vec4(shaderPosition(eye, anchor, unit), 0.0f);
    return out;
}

void SceneUniformBlock::upload(const Scene& scene, const glm::dvec3& eye, const glm::dvec3& anchor) {
    const ShaderScene numbers = shaderScene(scene, eye, anchor);
    SceneBlockData data{};
    std::copy(numbers.sphereGeometry.begin(), numbers.sphereGeometry.end(), data.sphereGeometry);
    std::copy(numbers.sphereSurface.begin(), numbers.sphereSurface.end(), data.sphereSurface);
    std::copy(numbers.sphereExtra.begin(), numbers.sphereExtra.end(), data.sphereExtra);
    std::copy(numbers.sphereEdgeTint.begin(), numbers.sphereEdgeTint.end(), data.sphereEdgeTint);
    std::copy(numbers.sphereFromCamera.begin(), numbers.sphereFromCamera.end(), data.sphereFromCamera);
    std::copy(numbers.lightPosition.begin(), numbers.lightPosition.end(), data.lightPosition);
    std::copy(numbers.lightIntensity.begin(), numbers.lightIntensity.end(), data.lightIntensity);
    std::copy(numbers.lightSurface.begin(), numbers.lightSurface.end(), data.lightSurface);
    data.cameraFromAnchor = numbers.cameraFromAnchor;
    gl::BindBuffer(GL_UNIFORM_BUFFER, buffer_);
    gl::BufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(data), &data);
}

void SceneUniformBlock::bind(const ShaderProgram& program) const {
    GLuint index = gl::GetUniformBlockIndex(program.id(), "SceneBlock");
    if (index == GL_INVALID_INDEX) return;  // a probe shader without the scene
    gl::UniformBlockBinding(program.id(), index, kSceneBlockBinding);
    gl::BindBufferBase(GL_UNIFORM_BUFFER, kSceneBlockBinding, buffer_);
}

namespace {
const char* const kViewNames[] = {"final",  "d",          "g",           "f",         "diffuse",
                                  "specular", "ndotl",    "shadow",      "normals",   "bounce",
                                  "fnv",    "irradiance", "prefiltered", "env-scale", "env-bias"};
}

View parseView(const std::string& name, int& bounce) {
    bounce = 0;
    for (int i = 0; i < int(std::size(kViewNames)); ++i)
        if (name == kViewNames[i] && i != int(View::Bounce)) return View(i);
    if (name.rfind("bounce", 0) == 0 && name.size() > 6 && name.size() < 9 &&
        name.find_first_not_of("0123456789", 6) == std::string::npos) {
        bounce = std::stoi(name.substr(6));
        return View::Bounce;
    }
    throw Error("--view: unknown view " + quotedValue(name) +
                " (expected final, d, g, f, fnv, diffuse, specular, ndotl, shadow, normals, irradiance, prefiltered, "
                "env-scale, env-bias or bounceK, e.g. bounce1)");
}

bool isPictureView(View view) { return view == View::Final || view == View::Bounce; }

std::string viewName(View view, int bounce) {
    if (view == View::Bounce) return "bounce" + std::to_string(bounce);
    return kViewNames[int(view)];
}

FrameSettings frameFromScene(const Scene& scene) {
    FrameSettings f;
    f.cameraToWorld = cameraToWorld(scene.camera);
    f.fovYRadians = scene.camera.fovYDegrees * 3.14159265358979323846 / 180.0;
    f.width = scene.render.width;
    f.height = scene.render.height;
    return f;
}

glm::mat4 shaderCameraBasis(const FrameSettings& frame) {
    double t = std::tan(0.5 * frame.fovYRadians);
    glm::dmat4 view = frame.cameraToWorld;
    view[0] *= t;
    view[1] *= t;
    view[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    return glm::mat4(view);
}

void setFrameUniforms(const ShaderProgram& p, const Scene& scene, const FrameSettings& frame) {
    const RenderSettings& r = scene.render;
    gl::UseProgram(p.id());
    // The camera basis only (its position is in the scene block, relative to the anchor),
    // with tan(fov_y / 2), in double, folded into right and up: the spec's
    // x r + y u + f with x, y computed at tan = 1 (u_fovY = pi/2) points the
    // same way, and a fov near 180 degrees no longer rounds past 90 in float.
    glm::mat4 camera = shaderCameraBasis(frame);
    gl::UniformMatrix4fv(p.uniform("u_cameraToWorld"), 1, GL_FALSE, glm::value_ptr(camera));
    gl::Uniform1f(p.uniform("u_fovY"), float(0.5 * 3.14159265358979323846));
    gl::Uniform2f(p.uniform("u_resolution"), float(frame.width), float(frame.height));
    gl::Uniform1i(p.uniform("u_spp"), r.spp);
    gl::Uniform1i(p.uniform("u_sphereCount"), int(scene.spheres.size()));
    gl::Uniform1i(p.uniform("u_lightCount"), int(scene.lights.size()));
    gl::Uniform1i(p.uniform("u_maxBounces"), r.maxBounces);
    gl::Uniform1f(p.uniform("u_ambient"), float(r.ambient));
    gl::Uniform3f(p.uniform("u_background"), float(r.background.x), float(r.background.y), float(r.background.z));
    gl::Uniform1f(p.uniform("u_exposure"), float(r.exposure));
    gl::Uniform1i(p.uniform("u_toneMap"), int(r.tonemap));
    gl::Uniform1f(p.uniform("u_gamma"), r.srgb ? 0.0f : float(r.gamma));
    gl::Uniform1i(p.uniform("u_view"), int(frame.view));
    gl::Uniform1i(p.uniform("u_viewBounce"), frame.viewBounce);
    glm::vec4 cutoff = bounceCutoffUniform(scene);  // read only by specialised shaders (trace.glsl)
    gl::Uniform4f(p.uniform("u_bounceCutoff"), cutoff.x, cutoff.y, cutoff.z, cutoff.w);
}

}  // namespace rl
