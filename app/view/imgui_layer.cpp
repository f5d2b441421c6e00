#include "view/imgui_layer.h"

#include <imgui.h>
#include <imgui_internal.h>  // the windows' rectangles (isOverUi)
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>

namespace rl {
namespace {
ImGuiStyle& baseStyle() {  // the unscaled style, so scaling twice does not compound
    static ImGuiStyle style;
    return style;
}
}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the student's working directory; the panel always starts the same
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    // Opaque: the window does not present the picture under the panel (on
    // llvmpipe each window pixel drawn costs; issue 37), and no text of the
    // picture's overlays shows through it.
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    baseStyle() = style;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    // GLSL 1.50 runs on both the 3.3 core context and macOS's 4.1 forward-compatible one.
    ImGui_ImplOpenGL3_Init("#version 150");
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::endFrame() {
    ImGui::Render();
    windows_.clear();
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        // Begun this frame (collapsed or not), shown, and not ImGui's implicit
        // "Debug##Default" window, which is never drawn but spans 400x400.
        if (w->LastFrameActive == ImGui::GetFrameCount() && !w->Hidden && !w->IsFallbackWindow)
            windows_.push_back({w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y});
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ImGuiLayer::setScale(float scale) {
    scale_ = std::clamp(scale, kMinScale, kMaxScale);
    ImGuiStyle& style = ImGui::GetStyle();
    style = baseStyle();
    style.ScaleAllSizes(scale_);
    ImGui::GetIO().FontGlobalScale = scale_;
}

bool ImGuiLayer::isOverUi(double x, double y) const {
    for (const Rect& r : windows_)
        if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) return true;
    return false;
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace rl
