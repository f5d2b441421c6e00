#include "bench/textbook.h"

#include "core/paths.h"
#include "gl/gl_api.h"
#include "shader/shader_library.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <filesystem>
#include <vector>

namespace rl::bench {

std::string textbookUnsupported() {
    std::error_code ec;
    if (std::filesystem::is_regular_file(shadersDir() / "yardstick" / "textbook.frag", ec)) return "";
    return "not in this copy: a student edition leaves shaders/yardstick/textbook.frag out (it writes the model's formulas)";
}

ShaderProgram buildTextbook() {
    Implementation none;  // the textbook includes nothing
    return ShaderProgram(assembleShader("fullscreen.vert", none, {}), assembleShader("yardstick/textbook.frag", none, {}));
}

void setTextbookUniforms(const ShaderProgram& p, const Scene& scene) {
    gl::UseProgram(p.id());
    auto set3 = [&](const char* name, const glm::dvec3& v) {
        gl::Uniform3f(p.uniform(name), float(v.x), float(v.y), float(v.z));
    };
    const Camera& c = scene.camera;
    glm::dvec3 f = glm::normalize(c.target - c.position);
    glm::dvec3 r = glm::normalize(glm::cross(f, c.up));
    glm::dvec3 u = glm::cross(r, f);
    double t = std::tan(c.fovYDegrees * 3.14159265358979323846 / 360.0);
    set3("tb_eye", c.position);
    set3("tb_right", r * t);
    set3("tb_up", u * t);
    set3("tb_forward", f);
    const RenderSettings& rs = scene.render;
    gl::Uniform2f(p.uniform("tb_resolution"), float(rs.width), float(rs.height));
    gl::Uniform1i(p.uniform("tb_gridSize"), int(std::lround(std::sqrt(double(rs.spp)))));
    gl::Uniform1i(p.uniform("tb_sphereCount"), int(scene.spheres.size()));
    gl::Uniform1i(p.uniform("tb_lightCount"), int(scene.lights.size()));
    gl::Uniform1i(p.uniform("tb_maxBounces"), rs.maxBounces);
    gl::Uniform1i(p.uniform("tb_toneMap"), int(rs.tonemap));
    gl::Uniform1f(p.uniform("tb_ambient"), float(rs.ambient));
    gl::Uniform1f(p.uniform("tb_exposure"), float(rs.exposure));
    gl::Uniform1f(p.uniform("tb_gamma"), rs.srgb ? 0.0f : float(rs.gamma));
    set3("tb_background", rs.background);

    std::vector<float> center, radius, albedo, material, lightPos, lightPower;
    for (const Sphere& s : scene.spheres) {
        center.insert(center.end(), {float(s.center.x), float(s.center.y), float(s.center.z)});
        radius.push_back(float(s.radius));
        const Material& m = s.material;
        albedo.insert(albedo.end(), {float(m.albedo.x), float(m.albedo.y), float(m.albedo.z)});
        material.insert(material.end(), {float(m.roughness), float(m.metallic), float(m.ao)});
    }
    for (const Light& l : scene.lights) {
        lightPos.insert(lightPos.end(), {float(l.position.x), float(l.position.y), float(l.position.z)});
        glm::dvec3 power = l.color * l.intensity;
        lightPower.insert(lightPower.end(), {float(power.x), float(power.y), float(power.z)});
    }
    auto n = [](const std::vector<float>& v, int per) { return GLsizei(v.size() / per); };
    if (!scene.spheres.empty()) {
        gl::Uniform3fv(p.uniform("tb_center"), n(center, 3), center.data());
        gl::Uniform1fv(p.uniform("tb_radius"), n(radius, 1), radius.data());
        gl::Uniform3fv(p.uniform("tb_albedo"), n(albedo, 3), albedo.data());
        gl::Uniform3fv(p.uniform("tb_material"), n(material, 3), material.data());
    }
    if (!scene.lights.empty()) {
        gl::Uniform3fv(p.uniform("tb_lightPos"), n(lightPos, 3), lightPos.data());
        gl::Uniform3fv(p.uniform("tb_lightPower"), n(lightPower, 3), lightPower.data());
    }
}

}  // namespace rl::bench
