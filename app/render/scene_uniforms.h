// Scene and camera to shader uniforms (the table is docs/uniforms.md).
// Sphere and light arrays go into one std140 uniform block (binding 0), the
// rest into plain uniforms whose locations the program caches.
#pragma once

#include "core/scene.h"
#include "gl/gl_api.h"
#include "shader/program.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace rl {

// The camera's basis as the spec defines it: f = normalize(target - position),
// r = normalize(cross(f, up)), u = cross(r, f). Columns: r, u, -f, position.
glm::dmat4 cameraToWorld(const Camera& camera);

// The camera's relation to a sphere (scene.glsl, u_sphereFromCamera): C =
// |e - c|^2 - r^2 from the world's eye and centre in long double, in the
// shader's unit, and whether the exercise's float32 |o - c|^2 - r^2 cannot tell its
// sign, so that camera rays take their root from C (issue #23: a camera 1e-3
// above a ground of radius 1e5). Recomputed for every camera position.
struct CameraSphere {
    double C = 0.0;
    bool hostDecides = false;
};
CameraSphere cameraSphere(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& anchor, double unit);

// The sphere whose surface light k lies on or within float32's reach of
// (-1: none; the nearest if several), and its side from double
// (lightSurfaceSide(): -1 inside, 0 on, 1 outside). scene.glsl, u_lightSurface.
struct LightOnSurface {
    int sphere = -1;
    int side = 0;
};
LightOnSurface lightOnSurface(const Scene& scene, std::size_t k, const glm::dvec3& anchor, double unit);

// The scene's numbers as the shader holds them (shaders/scene.glsl): spheres,
// lights and the camera `eye` relative to `anchor` (sceneAnchor()), in the
// shader's unit (shaderUnits()), computed in double and rounded to float32
// last, with each sphere's |centre - anchor|^2 - r^2 (docs/uniforms.md). The
// uniform block and the constants of a specialised program
// (render/scene_constants.h) both hold exactly these floats.
struct ShaderScene {
    std::vector<glm::vec4> sphereGeometry;    // xyz centre, w radius
    std::vector<glm::vec4> sphereSurface;     // rgb albedo, a perceptual roughness
    std::vector<glm::vec4> sphereExtra;       // x metallic, y ao, z |centre|^2 - r^2, w 1: refine its roots
    std::vector<glm::vec4> sphereEdgeTint;    // rgb edge tint
    std::vector<glm::vec4> sphereFromCamera;  // x |camera - centre|^2 - r^2, y 1: the host decides the side
    std::vector<glm::vec4> lightPosition;     // xyz position
    std::vector<glm::vec4> lightIntensity;    // rgb colour * intensity / unit^2
    std::vector<glm::vec4> lightSurface;      // x the sphere it lies on (-1), y its side
    glm::vec4 cameraFromAnchor{0.0f};
    double unit = 1.0;                        // the shader's length unit (a power of two)
};
ShaderScene shaderScene(const Scene& scene, const glm::dvec3& eye, const glm::dvec3& anchor);

class SceneUniformBlock {
public:
    SceneUniformBlock();
    ~SceneUniformBlock();
    SceneUniformBlock(const SceneUniformBlock&) = delete;
    SceneUniformBlock& operator=(const SceneUniformBlock&) = delete;

    // Spheres, lights and the camera `eye` relative to `anchor` (sceneAnchor()),
    // computed in double and rounded to float32 last, with each sphere's
    // |centre - anchor|^2 - r^2 (docs/uniforms.md). The frame drawn must be
    // seen from `eye`.
    void upload(const Scene& scene, const glm::dvec3& eye, const glm::dvec3& anchor);
    void bind(const ShaderProgram& program) const;

private:
    GLuint buffer_ = 0;
};

// Teaching views of shaders/views.glsl; VIEW_FINAL is the picture.
// FresnelNoV ("fnv") is F(n.v), the mirror bounce's weight, beside F (F(v.h)).
enum class View {
    Final = 0, D, G, F, Diffuse, Specular, NdotL, Shadow, Normals, Bounce, FresnelNoV,
    // environment light's terms (issue 24, shaders/views.glsl): black in a scene without an environment
    EnvIrradiance, EnvPrefiltered, EnvScale, EnvBias
};
View parseView(const std::string& name, int& bounce);  // "final", "d", ..., "bounce2", "fnv"; throws rl::Error
std::string viewName(View view, int bounce = 0);
// True for the views a picture program draws (final, bounce K); the term views need every view compiled in.
bool isPictureView(View view);

struct FrameSettings {
    glm::dmat4 cameraToWorld{1.0};
    double fovYRadians = 1.0471975511965976;
    int width = 1, height = 1;
    View view = View::Final;
    int viewBounce = 0;
    // Whether the frame also stores its radiance (the second RGBA32F target):
    // `raylab render` needs it (the PFM, the check for NaN and Inf), the live
    // view, which shows the display target, does not, nor do the bench's timed
    // frames, which time the live view's frame. Without it llvmpipe stores 16
    // bytes a pixel less: 1.2 ms of CPU a frame at 640x480 (docs/performance.md).
    bool radiance = true;
};
FrameSettings frameFromScene(const Scene& scene);

// The camera basis the shader gets (camera.glsl, u_cameraToWorld): right and
// up scaled by tan(fov_y / 2) in double, back, and a zero position column.
glm::mat4 shaderCameraBasis(const FrameSettings& frame);

// The camera position of a frame: what SceneUniformBlock::upload() needs.
inline glm::dvec3 framePosition(const FrameSettings& frame) { return glm::dvec3(frame.cameraToWorld[3]); }

// Sets every plain uniform of the ray tracer for `scene` and `frame`.
void setFrameUniforms(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame);

}  // namespace rl
