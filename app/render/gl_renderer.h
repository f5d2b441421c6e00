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

// What `raylab render`, the live view and the bench draw a picture with
// (definesFor(..., Purpose::Picture), render/define_table.h): the program
// and, where its defines allow it, the program for the tiles no camera ray
// of the model can hit a sphere in (sky_tiles.h).
//
// Where the programs check an assumption about the exercise files pixel by
// pixel (marksPixels(): the sky tiles' miss, shadow rays from the light's
// side), a pixel where it does not hold is marked, and drawn again by the
// program without the assumption (`exact`, the same files and scene): the
// picture is then what the exercise files compute, whatever they are. A
// correct file marks no pixel, and `exact` is never built.
struct PictureProgram {
    ShaderProgram program;
    std::optional<ShaderProgram> sky;
    bool marks = false;                           // program or sky mark pixels
    std::function<ShaderProgram()> buildExact;    // the program without the assumptions
    std::shared_ptr<ShaderProgram> exact;         // once built: draws the marked pixels of every frame
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
    // program everywhere else (one scissored draw per rectangle of tiles),
    // and where the picture's `exact` program is built, that program over
    // the marked pixels (the depth test skips the others).
    // Rows [rows0, rows1) only (GL rows, from the bottom; rows1 < 0: to the
    // top): one band of a picture that comes in over several frames (the
    // live view's still). Every pass keeps to the band (the depth clear, the
    // sky tiles, the exact redraw), so the bands together are the one-shot
    // frame, byte for byte.
    void draw(const PictureProgram& picture, const FrameSettings& frame, int rows0 = 0, int rows1 = -1);
    // Draws `picture` and, where the frame has marked pixels, builds its
    // exact program (once) and draws them again: the frame as the exercise
    // files compute it. Reads the frame back to look for marks only where
    // `look` is set (the live view: when the camera rests), the picture's
    // programs can mark one and `exact` is not built yet.
    // By bands (rows0, rows1 as draw()): the look at the whole frame (and the
    // exact redraw of its marks) comes with the band that reaches the top.
    void drawChecked(PictureProgram& picture, const FrameSettings& frame, bool look = true, int rows0 = 0,
                     int rows1 = -1);
    // Like draw(), measuring the GPU time with a GL_TIME_ELAPSED query (ms).
    double drawTimed(const ShaderProgram& program, const FrameSettings& frame);
    double drawTimed(const PictureProgram& picture, const FrameSettings& frame);
    // The last frame, rows top to bottom; its radiance is empty when that frame
    // did not store it (FrameSettings::radiance).
    Rendering readBack() const;
    // Whether the last frame has a pixel its program marked (alpha 0 in the
    // display target): an assumption that did not hold there.
    bool lastFrameMarked() const;
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
    GLuint depth_ = 0;               // the marks of a picture program (gl_FragDepth 0 where marked)
    GLuint timer_ = 0;
    int width_ = 0, height_ = 0;
    bool drawsRadiance_ = true;      // the draw buffers: both targets, or the display alone
    // The sky tiles of the last frame drawn with a sky program, for that frame's camera.
    std::optional<std::pair<FrameSettings, SkyTiles>> skyTiles_;
};

// One call for the common case: a current context, a program, a scene.
Rendering renderOnce(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame);
Rendering renderOnce(PictureProgram& picture, const Scene& scene, const FrameSettings& frame);
inline Rendering renderOnce(PictureProgram&& picture, const Scene& scene, const FrameSettings& frame) {
    return renderOnce(picture, scene, frame);
}

}  // namespace rl
