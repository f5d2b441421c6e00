// The browser edition's OpenGL context: WebGL2 (OpenGL ES 3.0) on an
// OffscreenCanvas, so that it works in a Worker as on the page. Replaces
// app/gl/context.cpp and context_egl.cpp in the web build (scripts/build-web.sh);
// every other GL file is the native one. Shaders are compiled as GLSL ES 3.00
// (shader_library.h's host dialect under __EMSCRIPTEN__).
// glcorearb.h's prototypes: every gl:: function is then resolved to
// emscripten's own WebGL2 implementation by name (resolve() below).
#define GL_GLEXT_PROTOTYPES 1
#include "gl/context.h"

#include "core/error.h"
#include "core/message.h"
#include "gl/gl_api.h"

#include <emscripten.h>
#include <emscripten/html5_webgl.h>

#include <cstring>

// One WebGL2 context for the whole module, created on first use: a browser
// keeps at most ~16 live contexts a page and drops the oldest, and the checker
// asks for a context per exercise. Returns the emscripten context handle, or
// 0 with the reason in the console (and `why`).
EM_JS(int, rl_web_create_webgl2, (), {
    // A Worker has no document: without OffscreenCanvas (Safari before 16.4) there is no context.
    var canvas = (typeof OffscreenCanvas !== 'undefined') ? new OffscreenCanvas(1, 1)
               : (typeof document !== 'undefined') ? document.createElement('canvas') : null;
    // No antialiasing, depth or alpha: raylab renders into its own RGBA32F framebuffers.
    var ctx = canvas && canvas.getContext('webgl2', {antialias: false, depth: false, stencil: false, alpha: false,
                                                     preserveDrawingBuffer: false, powerPreference: 'high-performance'});
    if (!ctx) return 0;
    // Rendering into RGBA32F (the display and radiance targets, the probe results) needs it.
    if (!ctx.getExtension('EXT_color_buffer_float')) return -1;
    var handle = GL.registerContext(ctx, {majorVersion: 2, minorVersion: 0, enableExtensionsByDefault: 1});
    GL.makeContextCurrent(handle);
    return handle;
});

// WebGL2 has no GL_TIME_ELAPSED readback (only an extension some browsers
// withhold), nor these two desktop calls: the bench's timer queries are never
// made here, but gl::load wants every function, so these answer "no result".
extern "C" {
void glGetQueryObjectiv(GLuint, GLenum, GLint* value) { *value = 0; }
void glGetQueryObjectui64v(GLuint, GLenum, GLuint64* value) { *value = 0; }
}

// What actually draws (SwiftShader, Mesa's llvmpipe through ANGLE, a GPU):
// WebGL's GL_RENDERER says only "WebKit WebGL".
EM_JS(void, rl_web_unmasked_renderer, (char* out, int size), {
    var ext = GLctx.getExtension('WEBGL_debug_renderer_info');
    var text = ext ? GLctx.getParameter(ext.UNMASKED_VENDOR_WEBGL) + ' | ' + GLctx.getParameter(ext.UNMASKED_RENDERER_WEBGL)
                   : 'renderer not disclosed';
    stringToUTF8(text, out, size);
});

namespace rl {

Backend parseBackend(const std::string& name) {
    if (name == "auto") return Backend::Auto;
    throw Error("--backend: the browser edition has one backend, WebGL2 (got " + quotedValue(name) + ")");
}

std::string backendName(Backend) { return "webgl2"; }

namespace {

class WebGlContext : public GlContext {
public:
    explicit WebGlContext(std::string description) : description_(std::move(description)) {}
    std::string description() const override { return description_; }
    bool hasTimerQueries() const override { return false; }

private:
    std::string description_;
};

void* resolve(const char* name) {
#define RAYLAB_WEB_RESOLVE(type, function) \
    if (std::strcmp(name, "gl" #function) == 0) return reinterpret_cast<void*>(&gl##function);
    RAYLAB_GL_FUNCTIONS(RAYLAB_WEB_RESOLVE)
#undef RAYLAB_WEB_RESOLVE
    return nullptr;
}

std::string webGlDescription() {
    auto str = [](GLenum name) {
        const GLubyte* s = gl::GetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    char renderer[256] = "";
    rl_web_unmasked_renderer(renderer, int(sizeof renderer));
    return "WebGL2 | " + std::string(renderer) + " | " + str(GL_VERSION);
}

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext(Backend) {
    static int handle = 0;
    static std::string description;
    if (handle <= 0) {
        handle = rl_web_create_webgl2();
        if (handle == 0)
            throw Error("this browser gives no WebGL2 context in a Worker (raylab needs WebGL2 and OffscreenCanvas)");
        if (handle < 0) {
            handle = 0;
            throw Error("this browser's WebGL2 cannot render into float32 targets (EXT_color_buffer_float)");
        }
        gl::load(resolve);
        description = webGlDescription();
    }
    emscripten_webgl_make_context_current(handle);
    return std::make_unique<WebGlContext>(description);
}

namespace detail {
std::string describeCurrentContext(const std::string& backend) { return backend + " | " + webGlDescription(); }
std::unique_ptr<GlContext> createEglContext(std::string& why) {
    why = "not in the browser";
    return nullptr;
}
std::unique_ptr<GlContext> createOsMesaContext(std::string& why) {
    why = "not in the browser";
    return nullptr;
}
}  // namespace detail

}  // namespace rl
