#include "view/asked_pixel_label.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace rl {
namespace {

constexpr float kMargin = 10.0f;  // from the window's edges, times the UI scale (as overlays.cpp)
constexpr float kGap = 8.0f;      // between the pixel and the label, times the UI scale
constexpr float kRing = 5.0f;     // the ring's radius around the pixel, times the UI scale
const ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;

float overlapArea(const LayoutRect& a, const LayoutRect& b) {
    const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
    return w > 0 && h > 0 ? w * h : 0.0f;
}

}  // namespace

LayoutRect askedPixelLabelBox(float x, float y, float width, float height, float windowWidth, float windowHeight,
                              float uiScale, const std::vector<LayoutRect>& avoid) {
    const float margin = kMargin * uiScale, gap = kGap * uiScale;
    const LayoutRect inside{margin, margin, windowWidth - margin, windowHeight - margin};
    const LayoutRect candidates[4] = {
        {x + gap, y + gap, x + gap + width, y + gap + height},
        {x + gap, y - gap - height, x + gap + width, y - gap},
        {x - gap - width, y + gap, x - gap, y + gap + height},
        {x - gap - width, y - gap - height, x - gap, y - gap},
    };
    LayoutRect best{};
    float bestCost = FLT_MAX;
    for (LayoutRect c : candidates) {
        // Moved inside the window (a label wider than the room left of the
        // pixel slides over; it never leaves the window).
        const float dx = std::max(inside.x0 - c.x0, 0.0f) - std::max(c.x1 - inside.x1, 0.0f);
        const float dy = std::max(inside.y0 - c.y0, 0.0f) - std::max(c.y1 - inside.y1, 0.0f);
        const bool moved = dx != 0 || dy != 0;
        c = {c.x0 + dx, c.y0 + dy, c.x1 + dx, c.y1 + dy};
        float cost = moved ? 1.0f : 0.0f;  // a label away from its pixel only where none fits beside it
        for (const LayoutRect& a : avoid) cost += overlapArea(c, a);
        // Covering the pixel itself hides what was asked.
        cost += overlapArea(c, {x - gap / 2, y - gap / 2, x + gap / 2, y + gap / 2});
        if (cost < bestCost) {
            bestCost = cost;
            best = c;
        }
        if (cost == 0) break;
    }
    return best;
}

LayoutRect drawAskedPixelLabel(const AskedPixelLabel& label, float uiScale, const std::vector<LayoutRect>& avoid) {
    if (label.lines.empty()) return {};
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float windowWidth = viewport->Size.x, windowHeight = viewport->Size.y;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float padding = 2 * style.WindowPadding.x;
    // The text's size at the UI scale, shrunk (down to scale 1) to fit the window.
    float textWidth = 0;
    for (const std::string& line : label.lines) textWidth = std::max(textWidth, ImGui::CalcTextSize(line.c_str()).x);
    const float room = windowWidth - 2 * kMargin * uiScale - padding;
    float fontScale = 1.0f;
    if (textWidth > room) fontScale = std::max(1.0f / std::max(uiScale, 1.0f), room / std::max(textWidth, 1.0f));
    const float wrap = std::min(textWidth * fontScale, room);
    int rows = 0;
    for (const std::string& line : label.lines)
        rows += std::max(1, int(std::ceil(ImGui::CalcTextSize(line.c_str()).x * fontScale / std::max(wrap, 1.0f) - 1e-3f)));
    const float width = wrap + padding + 1.0f;
    const float height = float(rows) * ImGui::GetTextLineHeightWithSpacing() * fontScale + 2 * style.WindowPadding.y;
    const LayoutRect box =
        askedPixelLabelBox(label.x, label.y, width, height, windowWidth, windowHeight, uiScale, avoid);

    const ImU32 colour = label.agrees ? IM_COL32(110, 240, 110, 255) : IM_COL32(255, 100, 90, 255);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 at(viewport->Pos.x + label.x, viewport->Pos.y + label.y);
    draw->AddCircle(at, kRing * uiScale, IM_COL32(0, 0, 0, 255), 0, 3.0f * uiScale);
    draw->AddCircle(at, kRing * uiScale, colour, 0, 1.5f * uiScale);

    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + box.x0, viewport->Pos.y + box.y0), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(box.x1 - box.x0, box.y1 - box.y0));
    ImGui::SetNextWindowBgAlpha(0.85f);
    LayoutRect drawn = box;
    if (ImGui::Begin("##asked-pixel-label", nullptr, kFlags)) {
        ImGui::SetWindowFontScale(fontScale);
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
        for (std::size_t k = 0; k < label.lines.size(); ++k) {
            const ImVec4 text = k == 0 ? ImGui::ColorConvertU32ToFloat4(colour) : ImVec4(1.0f, 1.0f, 1.0f, 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Text, text);
            ImGui::TextUnformatted(label.lines[k].c_str());
            ImGui::PopStyleColor();
        }
        ImGui::PopTextWrapPos();
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        drawn = {pos.x - viewport->Pos.x, pos.y - viewport->Pos.y, pos.x - viewport->Pos.x + size.x,
                 pos.y - viewport->Pos.y + size.y};
    }
    ImGui::End();
    return drawn;
}

}  // namespace rl
