// Draws a ViewCaption (view_caption.h) over the picture: a dark box at the
// bottom right with the view's name, the model, the formula and the colour
// bar. It has its own Dear ImGui context (text and shapes only, no input),
// so it is drawn right after the picture and BEFORE the picture's
// screenshot: captions are in every screenshot (P, --screenshot) and
// recording, with the panel shown or hidden. The panel (imgui_layer.h) is
// drawn later, over it.
#pragma once

#include "view/layout_report.h"
#include "view/view_caption.h"

#include <string>
#include <vector>

struct ImGuiContext;

namespace rl {

class CaptionLayer {
public:
    CaptionLayer();  // needs the window's GL context current
    ~CaptionLayer();
    CaptionLayer(const CaptionLayer&) = delete;
    CaptionLayer& operator=(const CaptionLayer&) = delete;

    // Where the caption went, framebuffer pixels (empty rectangles when not drawn).
    struct Placement {
        LayoutRect box, bar;              // the caption's box, its colour bar
        std::vector<LayoutRect> labels;   // the labels' boxes, in the order given
        bool compact = false;             // the model and scale lines left out to fit
        float scale = 0;                  // the UI scale it was drawn at (smaller to fit)
    };

    // Draws into the bound default framebuffer of width x height pixels.
    // Leaves the current ImGui context (the panel's) as it found it.
    // `rays` are drawn first, under the caption. `showCaption` false: the rays only.
    // `labels` (side by side) on dark boxes.
    // The caption keeps clear of `avoid` (the spheres on screen, the panel)
    // and of the top `topReserved` rows (the wipe's and side-by-side names):
    // at the bottom right where it fits, else at the top right, else without
    // its model and scale lines, else at a smaller scale (never below 1 or
    // half the UI scale); captionLayout() is where it goes with nothing to avoid.
    // Where nothing fits it is drawn small at the bottom right, or with
    // `yieldWhenNoRoom` (an error box has the room) not at all.
    Placement draw(const ViewCaption& caption, bool showCaption, const std::vector<OverlaySegment>& rays,
                   const std::vector<OverlayLabel>& labels, int width, int height, float uiScale,
                   const std::vector<LayoutRect>& avoid = {}, float topReserved = 0, bool yieldWhenNoRoom = false);

    // The size of `text` in the default font at `fontSize` pixels (the font
    // the panel and the wipe's names use too), for placing boxes before drawing.
    float textWidth(const std::string& text, float fontSize) const;

private:
    ImGuiContext* context_ = nullptr;
};

}  // namespace rl
