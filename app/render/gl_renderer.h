// Draws one full-screen triangle with a ray-tracing program into an offscreen
// framebuffer with two RGBA32F targets (display colour, linear radiance) and
// reads them back. Needs a current GL context (gl/context.h).
#pragma once

#include "core/image.h"
#include "core/scene.h"
#include "gl/gl_api.h"
#include "render/scene_uniforms.h"
#include "shader/program.h"

namespace rl {

class GlRenderer {
public:
    GlRenderer();
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // Uploads spheres and lights; call again whenever they change.
    void setScene(const Scene& scene);
    // Renders one frame into the offscreen targets (resized as needed).
    void draw(const ShaderProgram& program, const FrameSettings& frame);
    // Like draw(), measuring the GPU time with a GL_TIME_ELAPSED query (ms).
    double drawTimed(const ShaderProgram& program, const FrameSettings& frame);
    // The last frame, rows top to bottom.
    Rendering readBack() const;
    // The framebuffer holding the last frame (attachment 0 = display colour).
    GLuint framebuffer() const { return framebuffer_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void resize(int width, int height);
    Scene scene_;
    SceneUniformBlock sceneBlock_;
    bool uploaded_ = false;          // sceneBlock_ holds scene_ relative to uploadedEye_
    glm::dvec3 uploadedEye_{0.0};
    GLuint vertexArray_ = 0;
    GLuint framebuffer_ = 0;
    GLuint targets_[2] = {0, 0};
    GLuint timer_ = 0;
    int width_ = 0, height_ = 0;
};

// One call for the common case: a current context, a program, a scene.
Rendering renderOnce(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame);

}  // namespace rl
