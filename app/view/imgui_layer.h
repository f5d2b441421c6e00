// Dear ImGui on the GLFW window: set-up, one frame at a time, and the UI
// scale for projectors (font and every size scaled together).
#pragma once

#include <vector>

struct GLFWwindow;

namespace rl {

class ImGuiLayer {
public:
    // Install the window's own input callbacks BEFORE this: the GLFW backend
    // chains to the callbacks it finds installed.
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    // Draws the frame's UI into the bound (default) framebuffer.
    void endFrame();

    // 1 = ImGui's own sizes; 2 = twice the text and spacing (a projector at
    // the back of a lecture hall). Clamped to [kMinScale, kMaxScale].
    void setScale(float scale);
    float scale() const { return scale_; }
    static constexpr float kMinScale = 0.5f;  // below this the default font is unreadable
    static constexpr float kMaxScale = 4.0f;  // a 4K projector at 4x still fits the panel

    // True while ImGui uses the mouse (over the panel) or the keyboard (a text field).
    bool wantsMouse() const;
    // True when (x, y), in window units, lies on a window of the last frame
    // drawn (the panel, a popup, the help, the error box): what the user saw
    // under the pointer when pressing. ImGui 1.86's GLFW backend polls the
    // cursor only at NewFrame, so ImGui's own hover state can be stale by the
    // time a press made in the same instant as a move is handled.
    bool isOverUi(double x, double y) const;
    bool wantsKeyboard() const;

private:
    float scale_ = 1.0f;
    struct Rect {
        float x0, y0, x1, y1;
    };
    std::vector<Rect> windows_;  // the visible windows of the last frame
};

}  // namespace rl
