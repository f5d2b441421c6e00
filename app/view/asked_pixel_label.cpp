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
const ImGuiWindowFlags kFlags = ImGuiWindowFlags_NoDecoration |
                                ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoScrollbar;

float overlapArea(const LayoutRect& a, const LayoutRect& b) {
    const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
    return w > 0 && h > 0 ? w * h : 0.0f;
}

}  // namespace

LayoutRect askedPixelLabelBox(float x, float y, float width, float height, float windowWidth, float windowHeight,
                              float uiScale, const std::vector<LayoutRect>& avoid, float* overlap) {
    const float margin = kMargin * uiScale, gap = kGap * uiScale;
    const LayoutRect pixel{x - gap / 2, y - gap / 2, x + gap / 2, y + gap / 2};
    // Beside the pixel first; then beside the edges of what is in the way and
    // at the window's edges, the nearest free place winning.
    std::vector<float> xs = {x + gap, x - gap - width, margin, windowWidth - margin - width};
    std::vector<float> ys = {y + gap, y - gap - height, margin, windowHeight - margin - height};
    for (const LayoutRect& a : avoid) {
        if (a.empty()) continue;
        xs.insert(xs.end(), {a.x1 + gap, a.x0 - gap - width});
        ys.insert(ys.end(), {a.y1 + gap, a.y0 - gap - height});
    }
    LayoutRect best{};
    float bestCost = FLT_MAX, bestOverlap = FLT_MAX;
    for (float x0 : xs)
        for (float y0 : ys) {
            x0 = std::clamp(x0, margin, std::max(margin, windowWidth - margin - width));
            y0 = std::clamp(y0, margin, std::max(margin, windowHeight - margin - height));
            const LayoutRect c{x0, y0, x0 + width, y0 + height};
            float covered = overlapArea(c, pixel);
            for (const LayoutRect& a : avoid) covered += overlapArea(c, a);
            // Distance from the pixel to the box: the nearest free place.
            const float dx = std::max({c.x0 - x, x - c.x1, 0.0f}), dy = std::max({c.y0 - y, y - c.y1, 0.0f});
            const float cost = covered * 1e4f + dx + dy;
            if (cost < bestCost) {
                bestCost = cost;
                bestOverlap = covered;
                best = c;
            }
        }
    if (overlap) *overlap = bestOverlap;
    return best;
}

LayoutRect drawAskedPixelLabel(const AskedPixelLabel& label, float uiScale, const std::vector<LayoutRect>& avoid) {
    if (label.lines.empty()) return {};
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float windowWidth = viewport->Size.x, windowHeight = viewport->Size.y;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float padX = 2 * style.WindowPadding.x, padY = 2 * style.WindowPadding.y;
    const float lineGap = ImGui::GetTextLineHeightWithSpacing() - ImGui::GetTextLineHeight();
    float textWidth = 0;
    for (const std::string& line : label.lines) textWidth = std::max(textWidth, ImGui::CalcTextSize(line.c_str()).x);
    const float room = windowWidth - 2 * kMargin * uiScale - padX;
    // The layouts, most readable first: at the UI scale on one line each,
    // then smaller (down to UI scale 1), then wrapped narrower and narrower
    // (never below 14 characters); the first that finds a free place wins.
    struct Option { float fontScale, wrap; };
    std::vector<Option> options;
    const float smallest = 1.0f / std::max(uiScale, 1.0f);
    for (float f = 1.0f; f >= smallest - 1e-4f; f -= 0.25f * (1.0f - smallest) + 1e-4f)
        options.push_back({f, std::min(textWidth * f, room)});
    const float minWrap = ImGui::CalcTextSize("MMMMMMMMMMMMMM").x * smallest;
    for (float w = std::min(textWidth * smallest, room) * 0.8f; w >= minWrap; w *= 0.8f) options.push_back({smallest, w});
    LayoutRect box{};
    Option chosen = options.front();
    float leastOverlap = FLT_MAX;
    for (const Option& o : options) {
        // Sizes at this font scale: measured at the UI scale, wrapped at wrap / scale.
        float height = padY, width = 0;
        for (const std::string& line : label.lines) {
            const ImVec2 size = ImGui::CalcTextSize(line.c_str(), nullptr, false, o.wrap / o.fontScale);
            height += (size.y + lineGap) * o.fontScale;
            width = std::max(width, size.x * o.fontScale);
        }
        float overlap = 0;
        const LayoutRect b = askedPixelLabelBox(label.x, label.y, width + padX + 1.0f, height, windowWidth, windowHeight,
                                                uiScale, avoid, &overlap);
        if (overlap < leastOverlap) {
            leastOverlap = overlap;
            box = b;
            chosen = o;
        }
        if (overlap <= 0) break;
    }

    const ImU32 colour = label.agrees ? IM_COL32(110, 240, 110, 255) : IM_COL32(255, 100, 90, 255);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 at(viewport->Pos.x + label.x, viewport->Pos.y + label.y);
    draw->AddCircle(at, kRing * uiScale, IM_COL32(0, 0, 0, 255), 0, 3.0f * uiScale);
    draw->AddCircle(at, kRing * uiScale, colour, 0, 1.5f * uiScale);

    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + box.x0, viewport->Pos.y + box.y0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(box.x1 - box.x0, box.y1 - box.y0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    LayoutRect drawn = box;
    if (ImGui::Begin("##asked-pixel-label", nullptr, kFlags)) {
        ImGui::SetWindowFontScale(chosen.fontScale);
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + chosen.wrap + 1.0f);
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
