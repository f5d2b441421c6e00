#include "view/overlays.h"

#include "view/key_bindings.h"

#include <imgui.h>
#include <imgui_internal.h>  // BringWindowToDisplayFront, the rows' extent

#include <algorithm>
#include <cfloat>
#include <string>
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
// The wipe: a 2-pixel line is visible from the back of the room and hides
// little; labels sit 6 pixels from it in a dark box of 6 pixels padding.
constexpr float kDividerWidth = 2.0f;
constexpr float kLabelPad = 6.0f;
const ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoNav;
}  // namespace

HelpRects drawHelpOverlay(bool& open, int& page, int& pages, float uiScale, LayoutRect area) {
    if (!open) return {};
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = kMargin * uiScale;
    if (area.empty()) area = {margin, margin, viewport->Size.x - margin, viewport->Size.y - margin};
    // Every row: the input, what it does. Keys with no text of their own
    // (F2..F8) are listed under the first of their group.
    using Row = std::pair<const char*, const char*>;
    std::vector<Row> rows;
    for (const MouseBinding& m : mouseBindings()) rows.push_back({m.input, m.what});
    for (const KeyBinding& k : keyBindings())
        if (*k.what) rows.push_back({k.keys, k.what});
    const ImGuiStyle& style = ImGui::GetStyle();
    // Measured at the UI scale: the font as the panel's (FontGlobalScale).
    const float lineHeight = ImGui::GetTextLineHeight() + style.ItemSpacing.y;
    const float cellGap = 2 * style.CellPadding.x + style.ItemSpacing.x;  // at least what a table puts between columns
    const float width = area.x1 - area.x0 - 2 * style.WindowPadding.x;
    // The title bar, the padding, the footer line and a line's slack (the
    // table's own spacing between rows).
    const float height = area.y1 - area.y0 - ImGui::GetFrameHeight() - 2 * style.WindowPadding.y - 3 * lineHeight;
    float keyWidth = 0, whatWidth = 0;
    for (const Row& row : rows) {
        keyWidth = std::max(keyWidth, ImGui::CalcTextSize(row.first).x);
        whatWidth = std::max(whatWidth, ImGui::CalcTextSize(row.second).x);
    }
    // A layout: `groups` column pairs, the key column at most a third of a
    // pair (its long names, "left drag on the divider", wrap too), the
    // descriptions wrapped in the rest; rows fill a column to the height,
    // then the next column, then the next page.
    struct Layout {
        int groups = 1;
        float keyWrap = 0, wrap = 0;
        std::vector<std::vector<std::vector<std::size_t>>> pages;  // page -> column -> rows
    };
    auto layOut = [&](int groups) {
        Layout l;
        l.groups = groups;
        const float pair = width / float(groups);
        l.keyWrap = std::min(keyWidth, std::max(4 * ImGui::GetFontSize(), (pair - 2 * cellGap) / 3));
        l.wrap = std::min(whatWidth, pair - l.keyWrap - 2 * cellGap);
        if (l.wrap < 10 * ImGui::GetFontSize() && groups > 1) return l;  // too narrow: no pages, not chosen
        l.pages.push_back({{}});
        float used = 0;
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const float h = std::max(ImGui::CalcTextSize(rows[i].first, nullptr, false, l.keyWrap).y,
                                     ImGui::CalcTextSize(rows[i].second, nullptr, false, l.wrap).y) +
                            style.ItemSpacing.y + 2 * style.CellPadding.y;
            if (!l.pages.back().back().empty() && used + h > height) {
                used = 0;
                if (int(l.pages.back().size()) == groups) l.pages.push_back({});
                l.pages.back().push_back({});
            }
            used += h;
            l.pages.back().back().push_back(i);
        }
        return l;
    };
    // The fewest pages; of those, the fewest columns (the widest descriptions).
    Layout layout = layOut(1);
    for (int g = 2; g <= 3; ++g) {
        Layout l = layOut(g);
        if (!l.pages.empty() && l.pages.size() < layout.pages.size()) layout = std::move(l);
    }
    pages = int(layout.pages.size());
    page = std::clamp(page, 0, pages - 1);
    const auto& columns = layout.pages[std::size_t(page)];
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 0.5f * (area.x0 + area.x1), viewport->Pos.y + area.y0),
                            ImGuiCond_Always, ImVec2(0.5f, 0.0f));  // centred in the area, at its top
    ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: nothing under it shows through its text
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(area.x1 - area.x0, area.y1 - area.y0));
    HelpRects out;
    // Short: at UI scale 3 the title bar is narrow.
    const std::string title = pages > 1 ? "Keys " + std::to_string(page + 1) + "/" + std::to_string(pages) + "###help"
                                        : std::string("Keys###help");
    if (ImGui::Begin(title.c_str(), &open,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing)) {
        ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());  // over the error box and the toast
        const ImVec2 o = viewport->Pos;
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        out.box = {pos.x - o.x, pos.y - o.y, pos.x - o.x + size.x, pos.y - o.y + size.y};
        // The texts' own rectangles (a table clips what does not fit its
        // column, so the table's extent would hide a cut).
        out.rows = {out.box.x1, out.box.y1, out.box.x0, out.box.y0};
        auto text = [&](const char* t, float wrapWidth) {
            ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrapWidth);
            ImGui::TextUnformatted(t);
            ImGui::PopTextWrapPos();
            const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
            out.rows = {std::min(out.rows.x0, a.x - o.x), std::min(out.rows.y0, a.y - o.y),
                        std::max(out.rows.x1, b.x - o.x), std::max(out.rows.y1, b.y - o.y)};
        };
        std::size_t tallest = 0;
        for (const auto& c : columns) tallest = std::max(tallest, c.size());
        const int groups = int(columns.size());
        if (ImGui::BeginTable("##help", 2 * groups, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_PadOuterX)) {
            for (int g = 0; g < groups; ++g) {
                ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthFixed, layout.keyWrap);
                ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthFixed, layout.wrap);
            }
            for (std::size_t r = 0; r < tallest; ++r) {
                ImGui::TableNextRow();
                for (const auto& c : columns) {
                    ImGui::TableNextColumn();
                    if (r < c.size()) text(rows[c[r]].first, layout.keyWrap);
                    ImGui::TableNextColumn();
                    if (r < c.size()) text(rows[c[r]].second, layout.wrap);
                }
            }
            ImGui::EndTable();
        }
        ImGui::PushStyleColor(ImGuiCol_Text, style.Colors[ImGuiCol_TextDisabled]);
        text(page + 1 < pages ? "H: next page" : "H: close", width);
        ImGui::PopStyleColor();
    }
    ImGui::End();
    return out;
}

LayoutRect drawErrorOverlay(const std::vector<std::string>& errors, float uiScale, LayoutRect area, bool atTop) {
    if (errors.empty()) return {};
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = kMargin * uiScale;
    if (area.empty()) area = {margin, margin, viewport->Size.x - margin, viewport->Size.y - margin};
    const float maxHeight = std::min(area.y1 - area.y0, viewport->Size.y * kMaxErrorHeight);
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + area.x0, viewport->Pos.y + (atTop ? area.y0 : area.y1)),
                            ImGuiCond_Always, ImVec2(0.0f, atTop ? 0.0f : 1.0f));  // pivot: the corner it hangs from
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(area.x1 - area.x0, std::max(1.0f, maxHeight)));
    ImGui::SetNextWindowBgAlpha(kReadableAlpha);
    LayoutRect box;
    if (ImGui::Begin("##errors", nullptr, kOverlayFlags)) {
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        box = {pos.x - viewport->Pos.x, pos.y - viewport->Pos.y, pos.x - viewport->Pos.x + size.x,
               pos.y - viewport->Pos.y + size.y};
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
        // Wrapped inside the box's padding (local coordinates of the window).
        ImGui::PushTextWrapPos(area.x1 - area.x0 - ImGui::GetStyle().WindowPadding.x);
        for (const std::string& e : errors) ImGui::TextUnformatted(e.c_str());
        ImGui::TextDisabled("The last good picture stays on screen; saving a fix reloads it.");
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    ImGui::End();
    return box;
}

WipeLabels wipeLabelBoxes(float dividerX, float windowWidth, float minX, float leftWidth, float rightWidth,
                          float textHeight, float uiScale) {
    const float pad = kLabelPad * uiScale;
    const float top = pad;  // at the top, clear of the error box and the caption below
    const float rowHeight = textHeight + 2 * pad;
    const float left0 = std::max(minX, 0.0f) + pad;  // right of the panel
    auto box = [&](float x, float y, float width) { return LayoutRect{x, y, x + width + 2 * pad, y + rowHeight}; };
    // Beside the divider, each on its own side, in the first row.
    WipeLabels out;
    out.left = box(dividerX - leftWidth - 3 * pad, top, leftWidth);
    out.right = box(std::max(dividerX + pad, left0), top, rightWidth);
    const float nextRow = top + rowHeight + pad;
    if (out.left.x0 < left0) out.left = box(left0, nextRow, leftWidth);  // no room left of the divider: below, at the edge
    if (out.right.x1 > windowWidth - pad)
        out.right = box(std::max(left0, windowWidth - pad - rightWidth - 2 * pad), nextRow, rightWidth);
    // Both in one row and in each other's way: the right one a row lower.
    if (out.left.overlaps(out.right)) {
        out.right.y0 = std::max(out.left.y1, out.right.y0) + pad;
        out.right.y1 = out.right.y0 + rowHeight;
    }
    return out;
}

std::vector<LayoutRect> dividerPieces(float dividerX, float windowHeight, float uiScale,
                                      const std::vector<LayoutRect>& avoid) {
    const float half = 0.5f * kDividerWidth * uiScale, gap = 2 * uiScale;
    std::vector<std::pair<float, float>> cuts;
    for (const LayoutRect& a : avoid)
        if (!a.empty() && a.x0 < dividerX + half && dividerX - half < a.x1) cuts.push_back({a.y0 - gap, a.y1 + gap});
    std::sort(cuts.begin(), cuts.end());
    std::vector<LayoutRect> out;
    float y = 0;
    for (const auto& [y0, y1] : cuts) {
        if (y0 > y) out.push_back({dividerX - half, y, dividerX + half, y0});
        y = std::max(y, y1);
    }
    if (y < windowHeight) out.push_back({dividerX - half, y, dividerX + half, windowHeight});
    return out;
}

void drawWipeOverlay(const std::vector<LayoutRect>& divider, const WipeLabels& boxes, const std::string& left,
                     const std::string& right, float uiScale) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();  // over the picture, under the panel and help
    for (const LayoutRect& piece : divider)
        draw->AddRectFilled(ImVec2(piece.x0, piece.y0), ImVec2(piece.x1, piece.y1), IM_COL32(255, 255, 255, 220));
    const float pad = kLabelPad * uiScale;
    auto label = [&](const LayoutRect& box, const std::string& text) {
        draw->AddRectFilled(ImVec2(box.x0, box.y0), ImVec2(box.x1, box.y1), IM_COL32(0, 0, 0, 170));
        draw->AddText(ImVec2(box.x0 + pad, box.y0 + pad), IM_COL32(255, 255, 255, 255), text.c_str());
    };
    label(boxes.left, left);
    label(boxes.right, right);
}

LayoutRect drawToast(const std::string& message, float uiScale, float top, float maxWidth) {
    if (message.empty()) return {};
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = kMargin * uiScale;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - margin, viewport->Pos.y + std::max(top, margin)),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));  // pivot: its top-right corner
    if (maxWidth <= 0) maxWidth = viewport->Size.x - 2 * margin;
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(maxWidth, FLT_MAX));
    ImGui::SetNextWindowBgAlpha(kToastAlpha);
    LayoutRect box;
    if (ImGui::Begin("##toast", nullptr, kOverlayFlags)) {
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        box = {pos.x - viewport->Pos.x, pos.y - viewport->Pos.y, pos.x - viewport->Pos.x + size.x,
               pos.y - viewport->Pos.y + size.y};
        // One line where a smaller text (down to UI scale 1) makes it fit; wrapped beyond.
        const float padding = 2 * ImGui::GetStyle().WindowPadding.x;
        ImGui::SetWindowFontScale(1.0f);  // measured at the UI scale (the window keeps last frame's factor)
        const float width = ImGui::CalcTextSize(message.c_str()).x;
        if (width + padding > maxWidth)
            ImGui::SetWindowFontScale(std::max(1.0f / std::max(uiScale, 1.0f), (maxWidth - padding) / width));
        ImGui::PushTextWrapPos(maxWidth - padding / 2);
        ImGui::TextUnformatted(message.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
    return box;
}

}  // namespace rl
