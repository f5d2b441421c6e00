// The window backend: a GLFW window with an OpenGL 3.3 core context (4.1
// forward-compatible on macOS, the only core versions Apple offers), made
// current on the calling thread with gl:: loaded through glfwGetProcAddress.
// `raylab view` uses it; headless work uses a hidden one only where no EGL
// or OSMesa is built or starts (gl/context.h: --backend glfw).
#pragma once

#include "gl/context.h"

#include <string>

struct GLFWwindow;

namespace rl {

struct WindowSettings {
    int width = 640;  // initial size in screen coordinates (HiDPI: the framebuffer is larger)
    int height = 480;
    std::string title = "raylab";
    bool visible = true;  // false: hidden window, the last headless backend (see context.h)
    bool vsync = true;    // false: swap as fast as the driver allows (timing runs)
};

class GlfwWindowContext final : public GlContext {
public:
    // Throws rl::Error with one line when there is no window system
    // ("no window system (X11: The DISPLAY environment variable is missing) ...")
    // or no 3.3 core context.
    explicit GlfwWindowContext(const WindowSettings& settings);
    ~GlfwWindowContext() override;
    GlfwWindowContext(const GlfwWindowContext&) = delete;
    GlfwWindowContext& operator=(const GlfwWindowContext&) = delete;

    std::string description() const override { return description_; }
    GLFWwindow* window() const { return window_; }

    // Framebuffer size in pixels: what the picture is rendered at.
    void framebufferSize(int& width, int& height) const;
    // Fullscreen on the monitor the window is on, and back to the window's
    // previous position and size.
    void toggleFullscreen();
    bool fullscreen() const;

private:
    GLFWwindow* window_ = nullptr;
    std::string description_;
    int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
};

}  // namespace rl
