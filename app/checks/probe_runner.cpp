#include "checks/probe_runner.h"

#include "course/exercise_registry.h"

#include "core/error.h"
#include "render/scene_uniforms.h"

#include <algorithm>

namespace rl {

std::vector<std::array<float, 4>> runProbe(const ShaderProgram& program, const ProbeSpec& spec, const Scene* scene) {
    const int count = int(spec.cases.size());
    const int width = std::min(count, 256);  // cases per row; 6 input texels each
    const int height = (count + width - 1) / width;

    std::vector<float> inputs(std::size_t(width) * 6 * height * 4, 0.0f);
    for (int k = 0; k < count; ++k) {
        float* texel = &inputs[(std::size_t(k / width) * width * 6 + std::size_t(k % width) * 6) * 4];
        std::copy(spec.cases[k].in.begin(), spec.cases[k].in.end(), texel);
    }

    GLuint input = 0, target = 0, framebuffer = 0, vertexArray = 0;
    gl::GenTextures(1, &input);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, input);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width * 6, height, 0, GL_RGBA, GL_FLOAT, inputs.data());
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    gl::GenTextures(1, &target);
    gl::BindTexture(GL_TEXTURE_2D, target);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl::GenFramebuffers(1, &framebuffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    const GLenum buffers[1] = {GL_COLOR_ATTACHMENT0};
    gl::DrawBuffers(1, buffers);

    Scene empty;
    const Scene& s = scene ? *scene : empty;
    FrameSettings frame = frameFromScene(s);
    frame.width = width;
    frame.height = height;
    setFrameUniforms(program, s, frame);
    // The block is bound even for a probe without the scene (then an empty
    // one): the probe shader keeps SceneBlock active, and WebGL refuses a draw
    // while an active uniform block has no buffer (the browser edition, web/),
    // which desktop drivers let pass.
    SceneUniformBlock block;
    // Probe inputs are in the camera frame, and so are the hits they make:
    // the anchor is the camera.
    block.upload(s, framePosition(frame), framePosition(frame));
    block.bind(program);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, input);
    gl::Uniform1i(program.uniform("u_probeInputs"), 0);
    gl::Uniform1i(program.uniform("u_probeFunction"),
                  spec.programFunction ? *spec.programFunction
                  : spec.name == "reintersect" ? kReintersectProbe : probeFunctionId(spec.name));
    gl::Viewport(0, 0, width, height);
    gl::GenVertexArrays(1, &vertexArray);
    gl::BindVertexArray(vertexArray);
    gl::DrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<std::array<float, 4>> results(std::size_t(width) * height);
    gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, results.data());
    GLenum error = gl::GetError();

    gl::DeleteVertexArrays(1, &vertexArray);
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteTextures(1, &target);
    gl::DeleteTextures(1, &input);
    if (error != GL_NO_ERROR) throw Error("OpenGL error while running the probe " + spec.name + ": " + gl::errorName(error));
    results.resize(std::size_t(count));
    return results;
}

}  // namespace rl
