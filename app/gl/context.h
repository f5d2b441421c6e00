// An OpenGL 3.3 core context, made current on the calling thread, with the
// gl:: functions loaded. Headless backends (EGL, OSMesa, and a hidden GLFW
// window where neither is built: macOS, Windows) live here; the live
// window (GLFW) is in context_glfw.h. The backend is named and chosen in one
// place: createHeadlessContext().
#pragma once

#include <memory>
#include <string>

namespace rl {

enum class Backend { Auto, Egl, OsMesa, Glfw };

Backend parseBackend(const std::string& name);  // "auto" | "egl" | "osmesa" | "glfw", throws rl::Error
std::string backendName(Backend backend);

class GlContext {
public:
    virtual ~GlContext() = default;
    // e.g. "EGL (device platform) | NVIDIA Corporation | NVIDIA H100 ..."
    virtual std::string description() const = 0;
    // True when GL_TIME_ELAPSED queries are measured by the GPU.
    virtual bool hasTimerQueries() const { return true; }
};

// EGL first (device platform, then Mesa surfaceless, then the default
// display), then OSMesa, then a hidden GLFW window (3.3 core, never shown;
// needs a window system, e.g. Xvfb on a server). Each only where it is built
// (RAYLAB_WITH_EGL, RAYLAB_WITH_OSMESA, RAYLAB_WITH_GLFW). Throws rl::Error
// with one line saying what was tried and why each failed.
std::unique_ptr<GlContext> createHeadlessContext(Backend backend);

// Tells the C library to keep freed memory for the driver's next frame
// instead of returning it to the system (glibc; a no-op elsewhere). Called
// by createHeadlessContext() and the window's context; idempotent.
void keepDriverHeap();

namespace detail {
// Each returns nullptr and fills `why` when the backend cannot start.
std::unique_ptr<GlContext> createEglContext(std::string& why);
std::unique_ptr<GlContext> createOsMesaContext(std::string& why);
std::unique_ptr<GlContext> createHiddenGlfwContext(std::string& why);
// Common tail: loads gl:: through `resolve`, checks the version is >= 3.3.
std::string describeCurrentContext(const std::string& backend);
}  // namespace detail

}  // namespace rl
