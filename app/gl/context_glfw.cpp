// GLFW window + OpenGL context. GLFW is initialised here and terminated with
// the window: raylab opens at most one window per process.
#include "gl/context_glfw.h"

#include "core/error.h"
#include "gl/context.h"
#include "gl/gl_api.h"

#define GLFW_INCLUDE_NONE  // gl_api.h brings the GL declarations; GLFW must not add its own
#include <GLFW/glfw3.h>

#include <chrono>
#include <memory>
#include <thread>

namespace rl {
namespace {

// GLFW's description of its most recent error, or `fallback`.
std::string lastGlfwError(const std::string& fallback) {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? std::string(description) : fallback;
}

// The monitor that holds the window's centre, so fullscreen happens on the
// projector when the window was dragged there; the primary one otherwise.
GLFWmonitor* monitorOf(GLFWwindow* window) {
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetWindowPos(window, &x, &y);
    glfwGetWindowSize(window, &w, &h);
    const int cx = x + w / 2, cy = y + h / 2;
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    for (int i = 0; i < count; ++i) {
        int mx = 0, my = 0;
        glfwGetMonitorPos(monitors[i], &mx, &my);
        const GLFWvidmode* mode = glfwGetVideoMode(monitors[i]);
        if (mode && cx >= mx && cx < mx + mode->width && cy >= my && cy < my + mode->height) return monitors[i];
    }
    return glfwGetPrimaryMonitor();
}

}  // namespace

GlfwWindowContext::GlfwWindowContext(const WindowSettings& settings) {
    keepDriverHeap();
    if (!glfwInit())
        throw Error("no window system (" + lastGlfwError("glfwInit failed") + ")" +
                    (settings.visible ? "; use `raylab render` for pictures without a window" : ""));
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
#ifdef __APPLE__
    // macOS offers core profiles only as 3.2+ forward-compatible; 4.1 is its newest.
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_COCOA_RETINA_FRAMEBUFFER, GLFW_TRUE);  // full-resolution framebuffer on Retina
#else
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
#endif
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, settings.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // Windows/X11 HiDPI: size in logical units
    // The picture is display-encoded by the shader already; the window must not encode it again.
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);  // full-screen triangles only, no depth test
    glfwWindowHint(GLFW_STENCIL_BITS, 0);

    window_ = glfwCreateWindow(settings.width, settings.height, settings.title.c_str(), nullptr, nullptr);
    if (!window_) {
        std::string why = lastGlfwError("glfwCreateWindow failed");
        glfwTerminate();
        throw Error("no OpenGL 3.3 core window (" + why + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(settings.vsync ? 1 : 0);
    try {
        gl::load([](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
        description_ = detail::describeCurrentContext(settings.visible ? "GLFW" : "GLFW (hidden window)");
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
}

namespace detail {
std::unique_ptr<GlContext> createHiddenGlfwContext(std::string& why) {
    // Rendering goes into framebuffer objects: the window only carries the
    // context, so it is tiny and never shown, and vsync is irrelevant.
    WindowSettings hidden;
    hidden.width = 16;
    hidden.height = 16;
    hidden.title = "raylab (hidden)";
    hidden.visible = false;
    hidden.vsync = false;
    // A busy X server (Xvfb on a loaded CI machine) now and then refuses a
    // connection it accepts a moment later: three tries, 0.2 s apart.
    constexpr int kTries = 3;
    for (int attempt = 1;; ++attempt) {
        try {
            return std::make_unique<GlfwWindowContext>(hidden);
        } catch (const Error& e) {
            why = e.what();
            if (attempt == kTries || why.rfind("no window system", 0) != 0) return nullptr;
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    }
}
}  // namespace detail

GlfwWindowContext::~GlfwWindowContext() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindowContext::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

bool GlfwWindowContext::fullscreen() const { return glfwGetWindowMonitor(window_) != nullptr; }

void GlfwWindowContext::toggleFullscreen() {
    if (fullscreen()) {
        glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_, windowedHeight_, 0);
        return;
    }
    glfwGetWindowPos(window_, &windowedX_, &windowedY_);
    glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
    GLFWmonitor* monitor = monitorOf(window_);
    if (!monitor) return;  // no monitor known (e.g. a virtual display without RandR): stay windowed
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    if (!mode) return;
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

}  // namespace rl
