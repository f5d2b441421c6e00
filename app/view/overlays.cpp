#include "view/overlays.h"

#include "view/key_bindings.h"

#include <imgui.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace rl {
namespace {
// Red that stays readable on a projector: light enough on the dark box.
const ImVec4 kErrorText(1.0f, 0.45f, 0.4f, 1.0f);
// Distance from the window's edges (times the UI scale): clear of the edge
// and of ImGui's own 8-pixel window padding.
constexpr float kMargin = 10.0f;
// Background opacity of the help and the error box: text must stay readable
// over a bright picture; a toast is only glanced at, so more picture shows.
constexpr float kReadableAlpha = 0.92f;
constexpr float kToastAlpha = 0.75f;
// The error box never covers more than 60% of the window's height: the
// picture that is still running stays visible above it (it scrolls).
constexpr float kMaxErrorHeight = 0.6f;
// The help never exceeds 95% of the window (it scrolls): its edges stay visible.
constexpr float kMaxHelpSize = 0.95f;
// The wipe: a 2-pixel line is visible from the back of the room and hides
// little; labels sit 6 pixels from it in a dark box of 6 pixels padding.
constexpr float kDividerWidth = 2.0f;
constexpr float kLabelPad = 6.0f;
const ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoNav;
}  // namespace

void drawHelpOverlay(bool& open) {
    if (!open) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));  // centred
    ImGui::SetNextWindowBgAlpha(kReadableAlpha);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                        ImVec2(viewport->Size.x * kMaxHelpSize, viewport->Size.y * kMaxHelpSize));
    if (ImGui::Begin(
            "Keys and mouse (H or Escape closes)", &open,
            ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
        // Every row: the input, what it does. Keys with no text of their own
        // (F2..F8) are listed under the first of their group.
        std::vector<std::pair<const char*, const char*>> rows;
        for (const MouseBinding& m : mouseBindings()) rows.push_back({m.input, m.what});
        for (const KeyBinding& k : keyBindings())
            if (*k.what) rows.push_back({k.keys, k.what});
        // As many column pairs (up to 3) as it takes to fit the window: the
        // help never scrolls where it can spread sideways. Where no count of
        // pairs fits at the UI scale (at 2 on 1920x1080 three pairs are
        // wider than the window), the text shrinks until one does: the help
        // is for the lecturer, who reads it close up.
        ImGui::SetWindowFontScale(1.0f);  // measured at the UI scale (the window keeps last frame's factor)
        const ImGuiStyle& style = ImGui::GetStyle();
        const float lineHeight = ImGui::GetTextLineHeightWithSpacing();
        const float availableHeight = viewport->Size.y * kMaxHelpSize - 4 * lineHeight;  // title and padding
        const float availableWidth = viewport->Size.x * kMaxHelpSize - 2 * style.WindowPadding.x;
        float keyWidth = 0, whatWidth = 0;
        for (const auto& row : rows) {
            keyWidth = std::max(keyWidth, ImGui::CalcTextSize(row.first).x);
            whatWidth = std::max(whatWidth, ImGui::CalcTextSize(row.second).x);
        }
        const float pairWidth = keyWidth + whatWidth + 2 * (2 * style.CellPadding.x + style.ItemSpacing.x);
        int groups = 1;
        float fontScale = 0;
        for (int g = 1; g <= 3; ++g) {
            const int perColumn = (int(rows.size()) + g - 1) / g;
            const float fits = std::min({1.0f, availableWidth / (float(g) * pairWidth),
                                         availableHeight / (float(perColumn) * lineHeight)});
            if (fits > fontScale + 1e-3f) {
                fontScale = fits;
                groups = g;
            }
        }
        ImGui::SetWindowFontScale(std::max(fontScale, 0.5f));  // below half a line, scrolling is better than shrinking
        const int perGroup = (int(rows.size()) + groups - 1) / groups;
        if (ImGui::BeginTable("##help", 2 * groups, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_PadOuterX)) {
            for (int r = 0; r < perGroup; ++r) {
                ImGui::TableNextRow();
                for (int g = 0; g < groups; ++g) {
                    const int index = g * perGroup + r;
                    ImGui::TableNextColumn();
                    if (index < int(rows.size())) ImGui::TextUnformatted(rows[std::size_t(index)].first);
                    ImGui::TableNextColumn();
                    if (index < int(rows.size())) ImGui::TextUnformatted(rows[std::size_t(index)].second);
                }
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

void drawErrorOverlay(const std::vector<std::string>& errors, float uiScale) {
    if (errors.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = kMargin * uiScale;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + margin, viewport->Pos.y + viewport->Size.y - margin),
                            ImGuiCond_Always, ImVec2(0.0f, 1.0f));  // pivot: its bottom-left corner
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                        ImVec2(viewport->Size.x - 2 * margin, viewport->Size.y * kMaxErrorHeight));
    ImGui::SetNextWindowBgAlpha(kReadableAlpha);
    if (ImGui::Begin("##errors", nullptr, kOverlayFlags)) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
        ImGui::PushTextWrapPos(viewport->Size.x - 4 * margin);  // inside the box's own margin and padding
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
    draw->AddLine(ImVec2(dividerX, 0), ImVec2(dividerX, windowHeight), IM_COL32(255, 255, 255, 220),
                  kDividerWidth * uiScale);
    const float pad = kLabelPad * uiScale;
    const ImVec2 leftSize = ImGui::CalcTextSize(left.c_str());
    const ImVec2 rightSize = ImGui::CalcTextSize(right.c_str());
    const float top = 2 * pad;  // at the top, clear of the error box at the bottom
    const float nextRow = top + ImGui::GetFontSize() + 3 * pad;
    auto label = [&](float x, float y, const ImVec2& size, const std::string& text) {
        draw->AddRectFilled(ImVec2(x - pad, y - pad), ImVec2(x + size.x + pad, y + size.y + pad),
                            IM_COL32(0, 0, 0, 170));
        draw->AddText(ImVec2(x, y), IM_COL32(255, 255, 255, 255), text.c_str());
    };
    // Beside the divider; a name too long for its side moves to the window's
    // edge one row lower, so the two never overlap and neither leaves the window.
    const float windowWidth = ImGui::GetMainViewport()->Size.x;
    const float leftX = dividerX - leftSize.x - 2 * pad, rightX = dividerX + 2 * pad;
    if (leftX >= pad)
        label(leftX, top, leftSize, left);
    else
        label(pad, nextRow, leftSize, left);
    if (rightX + rightSize.x + pad <= windowWidth)
        label(rightX, top, rightSize, right);
    else
        label(std::max(pad, windowWidth - rightSize.x - pad), nextRow, rightSize, right);
}

void drawToast(const std::string& message, float uiScale) {
    if (message.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = kMargin * uiScale;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - margin, viewport->Pos.y + margin),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));  // pivot: its top-right corner
    ImGui::SetNextWindowBgAlpha(kToastAlpha);
    if (ImGui::Begin("##toast", nullptr, kOverlayFlags)) ImGui::TextUnformatted(message.c_str());
    ImGui::End();
}

}  // namespace rl
