#include "render/gl_renderer.h"

#include "core/error.h"
#include "core/float_range.h"
#include "render/define_table.h"

#include <algorithm>
#include <vector>

namespace rl {

GlRenderer::GlRenderer() {
    gl::GenVertexArrays(1, &vertexArray_);  // core profile draws need a bound VAO, even an empty one
    gl::GenFramebuffers(1, &framebuffer_);
    gl::GenTextures(2, targets_);
    gl::GenRenderbuffers(1, &depth_);
    gl::GenQueries(1, &timer_);
}

GlRenderer::~GlRenderer() {
    gl::DeleteQueries(1, &timer_);
    gl::DeleteRenderbuffers(1, &depth_);
    gl::DeleteTextures(2, targets_);
    gl::DeleteFramebuffers(1, &framebuffer_);
    gl::DeleteVertexArrays(1, &vertexArray_);
}

PictureProgram buildPictureProgram(const Implementation& impl, const ShaderDefines& defines) {
    PictureProgram picture;
    picture.program = buildRayTracer(impl, defines);
    std::optional<ShaderDefines> sky = skyProgramDefines(defines);
    if (sky) picture.sky = buildRayTracer(impl, *sky);
    picture.marks = marksPixels(defines) || (sky && marksPixels(*sky));
    if (picture.marks) picture.buildExact = [impl, exact = withoutAssumptions(defines)] { return buildRayTracer(impl, exact); };
    return picture;
}

void GlRenderer::setScene(const Scene& scene, const EnvironmentSettings& environment) {
    scene_ = scene;
    if (!scene.environment) {
        environment_.reset();
    } else {
        std::shared_ptr<const EnvironmentResources> resources = environmentResources(*scene.environment, environment);
        if (!environment_ || &environment_->resources() != resources.get())
            environment_ = std::make_unique<EnvironmentTextures>(resources);
    }
    skyTiles_.reset();
    uploaded_ = false;  // uploaded by draw(), relative to the frame's camera
}

void GlRenderer::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    GLint maxSide = 0;
    gl::GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSide);
    if (width > maxSide || height > maxSide)
        throw Error("render size " + size + ": this OpenGL driver allows at most " + std::to_string(maxSide) +
                    " pixels a side (GL_MAX_TEXTURE_SIZE); use a smaller --size or render.width/height");
    while (gl::GetError() != GL_NO_ERROR) {
    }
    width_ = width;
    height_ = height;
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    for (int i = 0; i < 2; ++i) {
        gl::BindTexture(GL_TEXTURE_2D, targets_[i]);
        gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, targets_[i], 0);
    }
    gl::BindRenderbuffer(GL_RENDERBUFFER, depth_);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl::DrawBuffers(2, buffers);
    drawsRadiance_ = true;
    GLenum status = gl::CheckFramebufferStatus(GL_FRAMEBUFFER);
    GLenum error = gl::GetError();
    if (status != GL_FRAMEBUFFER_COMPLETE || error != GL_NO_ERROR) {
        width_ = height_ = 0;  // nothing usable was allocated
        const long long mib = (long long)width * height * 36 >> 20;  // two RGBA32F targets, 16 bytes a pixel each, and depth
        throw Error("render size " + size + ": the driver cannot allocate the two RGBA32F targets (" +
                    std::to_string(mib) + " MiB" + (error != GL_NO_ERROR ? ", " + gl::errorName(error) : "") +
                    "); use a smaller --size or render.width/height");
    }
}

void GlRenderer::uploadFor(const FrameSettings& frame) {
    const glm::dvec3 eye = framePosition(frame);
    if (!uploaded_ || eye != uploadedEye_) {  // the live view's camera moves: the block follows it
        sceneBlock_.upload(scene_, eye, sceneAnchor(scene_));
        uploaded_ = true;
        uploadedEye_ = eye;
    }
}

const SkyTiles& GlRenderer::skyTilesFor(const FrameSettings& frame) {
    auto sameCamera = [&](const FrameSettings& f) {
        return f.cameraToWorld == frame.cameraToWorld && f.fovYRadians == frame.fovYRadians && f.width == frame.width &&
               f.height == frame.height;
    };
    if (!skyTiles_ || !sameCamera(skyTiles_->first)) skyTiles_.emplace(frame, skyTiles(scene_, frame));
    return skyTiles_->second;
}

void GlRenderer::prepare(const FrameSettings& frame) {
    resize(frame.width, frame.height);
    uploadFor(frame);
    skyTilesFor(frame);
}

void GlRenderer::draw(const ShaderProgram& program, const FrameSettings& frame) {
    resize(frame.width, frame.height);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    if (frame.radiance != drawsRadiance_) {  // the shader's o_radiance goes nowhere without it
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, frame.radiance ? GLenum(GL_COLOR_ATTACHMENT1) : GLenum(GL_NONE)};
        gl::DrawBuffers(2, buffers);
        drawsRadiance_ = frame.radiance;
    }
    gl::Viewport(0, 0, frame.width, frame.height);
    setFrameUniforms(program, scene_, frame);
    uploadFor(frame);
    sceneBlock_.bind(program);
    if (environment_ && scene_.environment) environment_->bind(program, *scene_.environment);
    gl::BindVertexArray(vertexArray_);
    gl::DrawArrays(GL_TRIANGLES, 0, 3);
    GLenum error = gl::GetError();
    if (error != GL_NO_ERROR) throw Error("OpenGL error while drawing: " + gl::errorName(error));
}

void GlRenderer::draw(const PictureProgram& picture, const FrameSettings& frame, int rows0, int rows1) {
    // A band: every pass below scissored to its rows (a tile to its part in them).
    const int y0 = std::clamp(rows0, 0, frame.height), y1 = rows1 < 0 ? frame.height : std::clamp(rows1, y0, frame.height);
    const bool banded = y0 > 0 || y1 < frame.height;
    const PixelRect band{0, y0, frame.width, y1 - y0};
    auto bandOnly = [&] {
        if (!banded) return;
        gl::Enable(GL_SCISSOR_TEST);
        gl::Scissor(band.x, band.y, band.width, band.height);
    };
    auto bandDone = [&] {
        if (banded) gl::Disable(GL_SCISSOR_TEST);
    };
    // The marks go into the depth buffer (cleared to 1, the mark 0) and the
    // exact program is drawn where the depth test passes: where the stored
    // depth is below its triangle's 0.5. llvmpipe tests depth before the
    // shader and skips every 8 pixels none of which passes.
    if (picture.marks) {
        resize(frame.width, frame.height);
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        const GLfloat one = 1.0f;
        bandOnly();
        gl::ClearBufferfv(GL_DEPTH, 0, &one);
        bandDone();
        gl::Enable(GL_DEPTH_TEST);
        gl::DepthFunc(GL_ALWAYS);
        gl::DepthMask(GL_TRUE);
    }
    const SkyTiles* tiles = picture.sky ? &skyTilesFor(frame) : nullptr;
    if (!tiles || tiles->sky.empty()) {
        bandOnly();
        draw(picture.program, frame);
        bandDone();
    } else {
        gl::Enable(GL_SCISSOR_TEST);
        auto tile = [&](const PixelRect& r, const ShaderProgram& program) {
            const int t0 = std::max(r.y, band.y), t1 = std::min(r.y + r.height, band.y + band.height);
            if (t1 <= t0 || r.width <= 0) return;  // outside the band
            gl::Scissor(r.x, t0, r.width, t1 - t0);
            draw(program, frame);
        };
        for (const PixelRect& r : tiles->sky) tile(r, *picture.sky);
        for (const PixelRect& r : tiles->scene) tile(r, picture.program);
        gl::Disable(GL_SCISSOR_TEST);
    }
    if (!picture.marks) return;
    gl::DepthMask(GL_FALSE);
    if (picture.exact) {
        gl::DepthFunc(GL_GREATER);
        bandOnly();
        draw(*picture.exact, frame);
        bandDone();
    }
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_DEPTH_TEST);
}

void GlRenderer::drawChecked(PictureProgram& picture, const FrameSettings& frame, bool look, int rows0, int rows1) {
    draw(picture, frame, rows0, rows1);
    const bool top = rows1 < 0 || rows1 >= frame.height;  // the last band: the whole frame is drawn
    if (!top || !look || !picture.marks || picture.exact || !lastFrameMarked()) return;
    picture.exact = std::make_shared<ShaderProgram>(picture.buildExact());
    // The marks of the frame just drawn are still in the depth buffer.
    gl::Enable(GL_DEPTH_TEST);
    gl::DepthMask(GL_FALSE);
    gl::DepthFunc(GL_GREATER);
    draw(*picture.exact, frame);
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_DEPTH_TEST);
}

bool GlRenderer::lastFrameMarked() const {
    std::vector<float> pixels(std::size_t(width_) * height_ * 4);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels.data());
    for (std::size_t i = 3; i < pixels.size(); i += 4)
        if (pixels[i] < 0.5f) return true;
    return false;
}

double GlRenderer::drawTimed(const PictureProgram& picture, const FrameSettings& frame) {
    return timed([&] { draw(picture, frame); });
}

double GlRenderer::drawTimed(const ShaderProgram& program, const FrameSettings& frame) {
    return timed([&] { draw(program, frame); });
}

double GlRenderer::timed(const std::function<void()>& drawing) {
    gl::BeginQuery(GL_TIME_ELAPSED, timer_);
    drawing();
    gl::EndQuery(GL_TIME_ELAPSED);
    GLuint64 nanoseconds = 0;
    gl::GetQueryObjectui64v(timer_, GL_QUERY_RESULT, &nanoseconds);  // waits for the GPU
    return double(nanoseconds) * 1e-6;
}

Rendering GlRenderer::readBack() const {
    Rendering out;
    std::vector<float> pixels(std::size_t(width_) * height_ * 4);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    out.display = {width_, height_, std::vector<std::uint8_t>(std::size_t(width_) * height_ * 3)};
    if (drawsRadiance_) out.radiance = {width_, height_, std::vector<float>(std::size_t(width_) * height_ * 3)};
    for (int target = 0; target < (drawsRadiance_ ? 2 : 1); ++target) {
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0 + target);
        gl::ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels.data());
        for (int y = 0; y < height_; ++y) {  // GL rows start at the bottom
            const float* row = &pixels[std::size_t(height_ - 1 - y) * width_ * 4];
            for (int x = 0; x < width_; ++x) {
                for (int c = 0; c < 3; ++c) {
                    if (target == 0)
                        out.display.at(x, y)[c] = quantize8(row[4 * x + c]);
                    else
                        out.radiance.at(x, y)[c] = row[4 * x + c];
                }
            }
        }
    }
    GLenum error = gl::GetError();
    if (error != GL_NO_ERROR) throw Error("OpenGL error while reading the image back: " + gl::errorName(error));
    return out;
}

Rendering renderOnce(const ShaderProgram& program, const Scene& scene, const FrameSettings& frame) {
    GlRenderer renderer;
    renderer.setScene(scene);
    renderer.draw(program, frame);
    return renderer.readBack();
}

Rendering renderOnce(PictureProgram& picture, const Scene& scene, const FrameSettings& frame) {
    GlRenderer renderer;
    renderer.setScene(scene);
    renderer.drawChecked(picture, frame);
    return renderer.readBack();
}

}  // namespace rl
