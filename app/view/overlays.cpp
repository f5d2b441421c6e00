#include "view/overlays.h"

#include "view/key_bindings.h"

#include <imgui.h>

#include <algorithm>

namespace rl {
namespace {
// Red that stays readable on a projector: light enough on the dark box.
const ImVec4 kErrorText(1.0f, 0.45f, 0.4f, 1.0f);
const ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoNav;
}  // namespace

void drawHelpOverlay(bool& open) {
    if (!open) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);  // text over a bright picture must stay readable
    // Never larger than the window (it scrolls instead): 95% leaves its edges visible.
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(viewport->Size.x * 0.95f, viewport->Size.y * 0.95f));
    if (ImGui::Begin("Keys and mouse (H or Escape closes)", &open,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_NoCollapse)) {
        // The second column starts after the longest key or mouse input, plus two spaces.
        float column = 0;
        for (const MouseBinding& m : mouseBindings()) column = std::max(column, ImGui::CalcTextSize(m.input).x);
        for (const KeyBinding& k : keyBindings()) column = std::max(column, ImGui::CalcTextSize(k.keys).x);
        column += ImGui::CalcTextSize("  ").x + ImGui::GetStyle().WindowPadding.x;
        for (const MouseBinding& m : mouseBindings()) {
            ImGui::TextUnformatted(m.input);
            ImGui::SameLine(column);
            ImGui::TextUnformatted(m.what);
        }
        ImGui::Separator();
        for (const KeyBinding& k : keyBindings()) {
            ImGui::TextUnformatted(k.keys);
            ImGui::SameLine(column);
            ImGui::TextUnformatted(k.what);
        }
    }
    ImGui::End();
}

void drawErrorOverlay(const std::vector<std::string>& errors, float uiScale) {
    if (errors.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = 10.0f * uiScale;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + margin, viewport->Pos.y + viewport->Size.y - margin),
                            ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(viewport->Size.x - 2 * margin, viewport->Size.y * 0.6f));
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("##errors", nullptr, kOverlayFlags)) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
        ImGui::PushTextWrapPos(viewport->Size.x - 4 * margin);
        for (const std::string& e : errors) ImGui::TextUnformatted(e.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
        ImGui::TextDisabled("The last good picture stays on screen; saving a fix reloads it.");
    }
    ImGui::End();
}

void drawWipeOverlay(float dividerX, float windowHeight, const std::string& left, const std::string& right,
                     float uiScale) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the picture, under the panel and help
    const float width = 2.0f * uiScale;  // visible from the back of the room, thin enough to hide little
    draw->AddLine(ImVec2(dividerX, 0), ImVec2(dividerX, windowHeight), IM_COL32(255, 255, 255, 220), width);
    const float pad = 6.0f * uiScale;
    const ImVec2 leftSize = ImGui::CalcTextSize(left.c_str());
    const ImVec2 rightSize = ImGui::CalcTextSize(right.c_str());
    const float y = 2 * pad;  // at the top, clear of the error box at the bottom
    auto label = [&](float x, const ImVec2& size, const std::string& text) {
        draw->AddRectFilled(ImVec2(x - pad, y - pad), ImVec2(x + size.x + pad, y + size.y + pad), IM_COL32(0, 0, 0, 170));
        draw->AddText(ImVec2(x, y), IM_COL32(255, 255, 255, 255), text.c_str());
    };
    label(dividerX - leftSize.x - 2 * pad, leftSize, left);
    label(dividerX + 2 * pad, rightSize, right);
}

void drawToast(const std::string& message, float uiScale) {
    if (message.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = 10.0f * uiScale;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - margin, viewport->Pos.y + margin),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.75f);
    if (ImGui::Begin("##toast", nullptr, kOverlayFlags)) ImGui::TextUnformatted(message.c_str());
    ImGui::End();
}

}  // namespace rl
