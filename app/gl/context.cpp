#include "gl/context.h"

#include "core/error.h"
#include "core/message.h"
#include "gl/gl_api.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rl {

void keepDriverHeap() {
#if defined(__GLIBC__)
    // llvmpipe allocates its scene's data blocks for every frame and frees
    // them after it; glibc then trims the heap's top and the next frame
    // faults the pages in again. A frame drawn as several scissored draws
    // (the sky tiles, the per-tile programs) needs more blocks: on the
    // course row, 6.8 ms of CPU a frame instead of 5.4 ms and 4.3 ms of wall
    // clock instead of 2.8 ms, 3,500 more page faults in 30 frames
    // (docs/performance.md, "The heap between frames"). Keeping up to 256 MiB
    // of freed memory at the heap's top, and serving blocks below 32 MiB from
    // the heap, costs no more than the peak the process already reached.
    static const bool once = [] {
        mallopt(M_MMAP_THRESHOLD, 32 << 20);
        mallopt(M_TRIM_THRESHOLD, 256 << 20);
        return true;
    }();
    (void)once;
#endif
}

Backend parseBackend(const std::string& name) {
    if (name == "auto") return Backend::Auto;
    if (name == "egl") return Backend::Egl;
    if (name == "osmesa") return Backend::OsMesa;
    if (name == "glfw") return Backend::Glfw;
    throw Error("--backend: unknown backend " + quotedValue(name) + " (expected auto, egl, osmesa or glfw)");
}

std::string backendName(Backend backend) {
    switch (backend) {
        case Backend::Auto: return "auto";
        case Backend::Egl: return "egl";
        case Backend::OsMesa: return "osmesa";
        case Backend::Glfw: return "glfw";
    }
    return "?";
}

std::unique_ptr<GlContext> createHeadlessContext(Backend backend) {
    keepDriverHeap();
    std::string tried;
    auto attempt = [&](const char* name, auto create) -> std::unique_ptr<GlContext> {
        std::string why;
        auto context = create(why);
        if (!context) tried += std::string(tried.empty() ? "" : "; ") + name + ": " + why;
        return context;
    };
    if (backend == Backend::Auto || backend == Backend::Egl) {
        if (auto c = attempt("EGL", detail::createEglContext)) return c;
    }
    if (backend == Backend::Auto || backend == Backend::OsMesa) {
        if (auto c = attempt("OSMesa", detail::createOsMesaContext)) return c;
    }
    if (backend == Backend::Auto || backend == Backend::Glfw) {
        if (auto c = attempt("GLFW", detail::createHiddenGlfwContext)) return c;
    }
    throw Error("no OpenGL 3.3 context could be created (tried " + tried +
                "); install Mesa with scripts/setup.sh");
}

namespace detail {

std::string describeCurrentContext(const std::string& backend) {
    auto str = [](GLenum name) {
        const GLubyte* s = gl::GetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    GLint major = 0, minor = 0;
    gl::GetIntegerv(GL_MAJOR_VERSION, &major);
    gl::GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 3 || (major == 3 && minor < 3))
        throw Error(backend + " gave OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                    ", raylab needs 3.3 core");
    return backend + " | " + str(GL_VENDOR) + " | " + str(GL_RENDERER) + " | " + str(GL_VERSION);
}

}  // namespace detail

#ifndef RAYLAB_WITH_EGL
namespace detail {
std::unique_ptr<GlContext> createEglContext(std::string& why) {
    why = "not built (RAYLAB_WITH_EGL=OFF)";
    return nullptr;
}
}  // namespace detail
#endif

#ifndef RAYLAB_WITH_OSMESA
namespace detail {
std::unique_ptr<GlContext> createOsMesaContext(std::string& why) {
    why = "not built (RAYLAB_WITH_OSMESA=OFF)";
    return nullptr;
}
}  // namespace detail
#endif

#ifndef RAYLAB_WITH_GLFW_CONTEXT
namespace detail {
std::unique_ptr<GlContext> createHiddenGlfwContext(std::string& why) {
    why = "not built (RAYLAB_WITH_GLFW=OFF)";
    return nullptr;
}
}  // namespace detail
#endif

}  // namespace rl
