// Draws one full-screen triangle with a ray-tracing program into an offscreen
// framebuffer with two RGBA32F targets (display colour, linear radiance) and
// reads them back. Needs a current GL context (gl/context.h).
#pragma once

#include "core/image.h"
#include "core/scene.h"
#include "gl/gl_api.h"
#include "render/environment_resources.h"
#include "render/scene_uniforms.h"
#include "render/sky_tiles.h"
#include "shader/program.h"
#include "shader/shader_library.h"

#include <functional>
#include <memory>
#include <optional>

namespace rl {

// What `raylab render` draws a picture with (definesFor(..., Purpose::Picture),
// render/define_table.h): the program and, where its defines allow it, the
// program for the tiles no camera ray can hit a sphere in (sky_tiles.h).
struct PictureProgram {
    ShaderProgram program;
    std::optional<ShaderProgram> sky;
    // Where non-empty, the frame drawn tile group by tile group instead: each
    // program over its rectangles (scissored), together the frame once; for
    // one camera and size only (render/course_program.h's per-tile programs).
    // A group's `program` may be empty: `program` above then draws it, with
    // the int array uniform `u_tile` set to `tileInts` first.
    struct Tiles {
        ShaderProgram program;
        std::vector<PixelRect> rects;
        std::vector<int> tileInts;
    };
    std::vector<Tiles> tiles;
};
PictureProgram buildPictureProgram(const Implementation& impl, const ShaderDefines& defines);

class GlRenderer {
public:
    GlRenderer();
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // Uploads spheres and lights; call again whenever they change. A scene
    // with an environment also gets its tables for `environment` (cached per
    // image and settings: render/environment_resources.h), bound by draw().
    void setScene(const Scene& scene, const EnvironmentSettings& environment = {});
    // What draw() would do first for `frame` that depends only on the scene
    // and the camera (the targets' size, the scene block's upload, the sky
    // tiles), done now: the bench calls it outside its clock.
    void prepare(const FrameSettings& frame);
    // Renders one frame into the offscreen targets (resized as needed).
    void draw(const ShaderProgram& program, const FrameSettings& frame);
    // The picture program where some camera ray may hit a sphere, its sky
    // program everywhere else (one scissored draw per rectangle of tiles).
    void draw(const PictureProgram& picture, const FrameSettings& frame);
    // Like draw(), measuring the GPU time with a GL_TIME_ELAPSED query (ms).
    double drawTimed(const ShaderProgram& program, const FrameSettings& frame);
    double drawTimed(const PictureProgram& picture, const FrameSettings& frame);
    // The last frame, rows top to bottom; its radiance is empty when that frame
    // did not store it (FrameSettings::radiance).
    Rendering readBack() const;
    // The framebuffer holding the last frame (attachment 0 = display colour).
    GLuint framebuffer() const { return framebuffer_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void resize(int width, int height);
    double timed(const std::function<void()>& drawing);  // ms of GL_TIME_ELAPSED around it
    void uploadFor(const FrameSettings& frame);              // the scene block, relative to the frame's camera
    const SkyTiles& skyTilesFor(const FrameSettings& frame);  // cached per camera
    Scene scene_;
    std::unique_ptr<EnvironmentTextures> environment_;  // for scene_.environment, else null
    SceneUniformBlock sceneBlock_;
    bool uploaded_ = false;          // sceneBlock_ holds scene_ relative to uploadedEye_
    glm::dvec3 uploadedEye_{0.0};
    GLuint vertexArray_ = 0;
    GLuint framebuffer_ = 0;
    GLuint targets_[2] = {0, 0};
    GLuint timer_ = 0;
    int width_ = 0, height_ = 0;
    bool drawsRadiance_ = true;      // the draw buffers: both targets, or the display alone
    // The sky tiles of the last frame drawn with a sky program, for that frame's camera.
    std::optional<std::pair<FrameSettings, SkyTiles>> skyTiles_;
};

// One call for the common case: a current context, a program, a scene.
Rendering renderOnce(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame);
Rendering renderOnce(const PictureProgram& picture, const Scene& scene, const FrameSettings& frame);

}  // namespace rl
