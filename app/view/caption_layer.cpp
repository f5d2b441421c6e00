#include "view/caption_layer.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>

namespace rl {
namespace {
// The box: dark and mostly opaque, so white text reads over a white sphere.
const ImU32 kBox = IM_COL32(0, 0, 0, 190);
const ImU32 kTitle = IM_COL32(255, 255, 255, 255);
const ImU32 kText = IM_COL32(220, 220, 220, 255);
const ImU32 kFormula = IM_COL32(255, 220, 130, 255);  // the formula stands out in amber, as on a slide

// Switches to `context` and back (the panel's context stays current elsewhere).
class ContextScope {
public:
    explicit ContextScope(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(context);
    }
    ~ContextScope() { ImGui::SetCurrentContext(previous_); }

private:
    ImGuiContext* previous_;
};
}  // namespace

CaptionLayer::CaptionLayer() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ImGui_ImplOpenGL3_Init("#version 150");  // as imgui_layer.cpp: the 3.3 core and macOS's 4.1 contexts
    ImGui::SetCurrentContext(previous);
}

CaptionLayer::~CaptionLayer() {
    ContextScope scope(context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(nullptr);  // the scope restores the panel's
}

void CaptionLayer::draw(const ViewCaption& caption, bool showCaption, const std::vector<OverlaySegment>& rays,
                        const std::vector<OverlayLabel>& labels, int width, int height, float uiScale) {
    if (width <= 0 || height <= 0) return;
    ContextScope scope(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));  // framebuffer pixels, as captionLayout()
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();

    const CaptionLayout l = captionLayout(width, height, uiScale);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    // Rays: 2 px lines (scaled) with a dark outline, visible on any picture.
    for (const OverlaySegment& r : rays) {
        draw->AddLine(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), IM_COL32(0, 0, 0, 200), 4 * l.scale);
        draw->AddLine(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), r.colour, 2 * l.scale);
    }
    for (const OverlayLabel& label : labels) {
        const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(l.fontSize, FLT_MAX, 0, label.text.c_str());
        draw->AddRectFilled(ImVec2(label.x, label.y), ImVec2(label.x + size.x + 2 * l.pad, label.y + size.y + 2 * l.pad),
                            kBox, 4 * l.scale);
        draw->AddText(ImGui::GetFont(), l.fontSize, ImVec2(label.x + l.pad, label.y + l.pad), kTitle, label.text.c_str());
    }
    if (!showCaption) {
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        return;
    }
    ImFont* font = ImGui::GetFont();
    const float size = l.fontSize, s = l.scale;

    // The lines above the bar, bottom up: scale label, formula, model, title.
    struct Line {
        const std::string* text;
        ImU32 colour;
    };
    const Line lines[] = {{&caption.title, kTitle},
                          {&caption.model, kText},
                          {&caption.formula, kFormula},
                          {&caption.scale.label, kText}};
    float widest = l.barWidth, textHeight = 0;
    ImVec2 sizes[4];
    for (int i = 0; i < 4; ++i) {
        sizes[i] = font->CalcTextSizeA(size, FLT_MAX, l.textWidth, lines[i].text->c_str());
        widest = std::max(widest, sizes[i].x);
        textHeight += sizes[i].y + 2 * s;
    }
    const float left = l.right - l.pad - widest;
    const float top = l.barY - 4 * s - textHeight;
    draw->AddRectFilled(ImVec2(left - l.pad, top - l.pad), ImVec2(l.right, l.bottom), kBox, 4 * s);
    float y = top;
    for (int i = 0; i < 4; ++i) {
        draw->AddText(font, size, ImVec2(left, y), lines[i].colour, lines[i].text->c_str(), nullptr, l.textWidth);
        y += sizes[i].y + 2 * s;
    }

    // The ramp: grey level = position, exactly what the shader wrote.
    const ImVec2 bar0(l.barX, l.barY), bar1(l.barX + l.barWidth, l.barY + l.barHeight);
    draw->AddRectFilledMultiColor(bar0, bar1, IM_COL32(0, 0, 0, 255), IM_COL32(255, 255, 255, 255),
                                  IM_COL32(255, 255, 255, 255), IM_COL32(0, 0, 0, 255));
    // Ticks below the ramp (never over it: the ramp stays a clean ramp);
    // a label that would overlap the previous one is left out.
    float lastRight = -FLT_MAX;
    for (const ColourScale::Tick& t : caption.scale.ticks) {
        const float x = l.barX + float(t.position) * l.barWidth;
        draw->AddLine(ImVec2(x, bar1.y), ImVec2(x, bar1.y + 4 * s), kTitle, std::max(1.0f, s));
        const ImVec2 textSize = font->CalcTextSizeA(size, FLT_MAX, 0, t.text.c_str());
        const float textX = std::clamp(x - textSize.x / 2, left, l.right - l.pad - textSize.x);
        if (textX < lastRight + 4 * s) continue;
        draw->AddText(font, size, ImVec2(textX, bar1.y + 4 * s), kText, t.text.c_str());
        lastRight = textX + textSize.x;
    }

    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace rl
