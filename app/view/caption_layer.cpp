#include "view/caption_layer.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <optional>

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
    io.Fonts->AddFontDefault();  // built now: textWidth() measures before the first frame
    io.Fonts->Build();
    ImGui_ImplOpenGL3_Init("#version 150");  // as imgui_layer.cpp: the 3.3 core and macOS's 4.1 contexts
    ImGui::SetCurrentContext(previous);
}

float CaptionLayer::textWidth(const std::string& text, float fontSize) const {
    ContextScope scope(context_);
    return ImGui::GetIO().Fonts->Fonts[0]->CalcTextSizeA(fontSize, FLT_MAX, 0, text.c_str()).x;
}

CaptionLayer::~CaptionLayer() {
    ContextScope scope(context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(nullptr);  // the scope restores the panel's
}

CaptionLayer::Placement CaptionLayer::draw(const ViewCaption& caption, bool showCaption,
                                           const std::vector<OverlaySegment>& rays,
                                           const std::vector<OverlayLabel>& labels, int width, int height,
                                           float uiScale, const std::vector<LayoutRect>& avoid, float topReserved,
                                           bool yieldWhenNoRoom) {
    Placement placed;
    if (width <= 0 || height <= 0) return placed;
    ContextScope scope(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));  // framebuffer pixels, as captionLayout()
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();

    const CaptionLayout base = captionLayout(width, height, uiScale);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    ImFont* font = ImGui::GetFont();
    // Rays: 2 px lines (scaled) with a dark outline, visible on any picture.
    for (const OverlaySegment& r : rays) {
        draw->AddLine(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), IM_COL32(0, 0, 0, 200), 4 * base.scale);
        draw->AddLine(ImVec2(r.x0, r.y0), ImVec2(r.x1, r.y1), r.colour, 2 * base.scale);
    }
    for (const OverlayLabel& label : labels) {
        const float wrap = label.wrap > 0 ? std::max(1.0f, label.wrap - 2 * base.pad) : 0.0f;
        // Wrapped between words, never inside one ("Blinn-Phon / g"): a word
        // wider than the room makes the label's text smaller, down to UI
        // scale 1 (or half the UI scale).
        float fontSize = base.fontSize;
        if (wrap > 0) {
            float widestWord = 0;
            std::size_t start = 0;
            while (start < label.text.size()) {
                std::size_t end = label.text.find(' ', start);
                if (end == std::string::npos) end = label.text.size();
                const std::string word = label.text.substr(start, end - start);
                widestWord = std::max(widestWord, font->CalcTextSizeA(fontSize, FLT_MAX, 0, word.c_str()).x);
                start = end + 1;
            }
            const float floor = std::min(base.fontSize, 13.0f * std::max(1.0f, 0.5f * base.scale));
            if (widestWord > wrap) fontSize = std::max(floor, fontSize * wrap / widestWord);
        }
        const ImVec2 size = font->CalcTextSizeA(fontSize, FLT_MAX, wrap, label.text.c_str());
        const LayoutRect box{label.x, label.y, label.x + size.x + 2 * base.pad, label.y + size.y + 2 * base.pad};
        draw->AddRectFilled(ImVec2(box.x0, box.y0), ImVec2(box.x1, box.y1), kBox, 4 * base.scale);
        draw->AddText(font, fontSize, ImVec2(label.x + base.pad, label.y + base.pad), kTitle, label.text.c_str(),
                      nullptr, wrap);
        placed.labels.push_back(box);
        topReserved = std::max(topReserved, box.y1);  // the caption stays below the names
    }
    if (!showCaption) {
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        return placed;
    }

    // The lines above the bar, bottom up: scale label, formula, model, title;
    // compact: the title and the formula only.
    struct Line {
        const std::string* text;
        ImU32 colour;
        bool compact;  // kept in the compact caption
    };
    const Line lines[] = {{&caption.title, kTitle, true},
                          {&caption.model, kText, false},
                          {&caption.formula, kFormula, true},
                          {&caption.scale.label, kText, false}};
    // One candidate: where its box, bar and lines go.
    struct Geometry {
        CaptionLayout l;
        bool compact = false;
        float left = 0, top = 0;
        ImVec2 sizes[4];
        LayoutRect box;
    };
    auto geometry = [&](float scale, bool compact, bool atTop) {
        Geometry g;
        g.l = captionLayout(width, height, scale);
        g.compact = compact;
        float widest = g.l.barWidth, textHeight = 0;
        for (int i = 0; i < 4; ++i) {
            g.sizes[i] = compact && !lines[i].compact
                             ? ImVec2(0, 0)
                             : font->CalcTextSizeA(g.l.fontSize, FLT_MAX, g.l.textWidth, lines[i].text->c_str());
            if (compact && !lines[i].compact) continue;
            widest = std::max(widest, g.sizes[i].x);
            textHeight += g.sizes[i].y + 2 * g.l.scale;
        }
        g.left = g.l.right - g.l.pad - widest;
        g.top = g.l.barY - 4 * g.l.scale - textHeight;
        if (atTop) {  // the same box, moved up under the reserved rows
            const float dy = (topReserved + g.l.margin + g.l.pad) - g.top;
            g.top += dy;
            g.l.barY += dy;
            g.l.bottom += dy;
        }
        g.box = {g.left - g.l.pad, g.top - g.l.pad, g.l.right, g.l.bottom};
        return g;
    };
    auto fits = [&](const Geometry& g) {
        if (g.box.x0 < 0 || g.box.y0 < topReserved || g.box.y1 > float(height)) return false;
        for (const LayoutRect& a : avoid)
            if (g.box.overlaps(a)) return false;
        return true;
    };
    std::optional<Geometry> chosen;
    const float smallest = std::min(uiScale, std::max(1.0f, 0.5f * uiScale));
    std::vector<float> scales;  // 15% steps down to the floor, the floor itself last
    for (float scale = uiScale; scale > smallest + 1e-3f; scale *= 0.85f) scales.push_back(scale);
    scales.push_back(smallest);
    for (float scale : scales)
        for (bool compact : {false, true})
            for (bool atTop : {false, true}) {
                if (chosen) break;
                Geometry g = geometry(scale, compact, atTop);
                if (fits(g)) chosen = g;
            }
    if (!chosen && yieldWhenNoRoom) {
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        return placed;
    }
    if (!chosen) chosen = geometry(smallest, true, false);  // nothing fits: the smallest at its usual place
    const Geometry& g = *chosen;
    const CaptionLayout& l = g.l;
    const float size = l.fontSize, s = l.scale;
    placed.box = g.box;
    placed.bar = {l.barX, l.barY, l.barX + l.barWidth, l.barY + l.barHeight};
    placed.compact = g.compact;
    placed.scale = s;

    draw->AddRectFilled(ImVec2(g.box.x0, g.box.y0), ImVec2(g.box.x1, g.box.y1), kBox, 4 * s);
    float y = g.top;
    for (int i = 0; i < 4; ++i) {
        if (g.compact && !lines[i].compact) continue;
        draw->AddText(font, size, ImVec2(g.left, y), lines[i].colour, lines[i].text->c_str(), nullptr, l.textWidth);
        y += g.sizes[i].y + 2 * s;
    }

    // The ramp: grey level = position, exactly what the shader wrote.
    const ImVec2 bar0(l.barX, l.barY), bar1(l.barX + l.barWidth, l.barY + l.barHeight);
    if (caption.scale.swatches && !caption.scale.ticks.empty()) {
        // One swatch per value, in the grey the shader writes for it (the
        // tick sits at the swatch's centre: position (i + 0.5) / n).
        const float w = l.barWidth / float(caption.scale.ticks.size());
        for (size_t i = 0; i < caption.scale.ticks.size(); ++i) {
            const int grey = caption.scale.ticks.size() == 1 ? 255 : int(255 * i / (caption.scale.ticks.size() - 1));
            draw->AddRectFilled(ImVec2(bar0.x + w * float(i), bar0.y), ImVec2(bar0.x + w * float(i + 1), bar1.y),
                                IM_COL32(grey, grey, grey, 255));
        }
        draw->AddRect(bar0, bar1, kTitle, 0, 0, std::max(1.0f, s));
    } else {
        draw->AddRectFilledMultiColor(bar0, bar1, IM_COL32(0, 0, 0, 255), IM_COL32(255, 255, 255, 255),
                                      IM_COL32(255, 255, 255, 255), IM_COL32(0, 0, 0, 255));
    }
    // Ticks below the ramp (never over it: the ramp stays a clean ramp);
    // a label that would overlap the previous one is left out.
    float lastRight = -FLT_MAX;
    for (const ColourScale::Tick& t : caption.scale.ticks) {
        const float x = l.barX + float(t.position) * l.barWidth;
        draw->AddLine(ImVec2(x, bar1.y), ImVec2(x, bar1.y + 4 * s), kTitle, std::max(1.0f, s));
        const ImVec2 textSize = font->CalcTextSizeA(size, FLT_MAX, 0, t.text.c_str());
        const float textX = std::clamp(x - textSize.x / 2, g.left, l.right - l.pad - textSize.x);
        if (textX < lastRight + 4 * s) continue;
        draw->AddText(font, size, ImVec2(textX, bar1.y + 4 * s), kText, t.text.c_str());
        lastRight = textX + textSize.x;
    }

    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return placed;
}

}  // namespace rl
