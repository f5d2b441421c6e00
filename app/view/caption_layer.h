// Draws a ViewCaption (view_caption.h) over the picture: a dark box at the
// bottom right with the view's name, the model, the formula and the colour
// bar. It has its own Dear ImGui context (text and shapes only, no input),
// so it is drawn right after the picture and BEFORE the picture's
// screenshot: captions are in every screenshot (P, --screenshot) and
// recording, with the panel shown or hidden. The panel (imgui_layer.h) is
// drawn later, over it.
#pragma once

#include "view/view_caption.h"

#include <vector>

struct ImGuiContext;

namespace rl {

class CaptionLayer {
public:
    CaptionLayer();  // needs the window's GL context current
    ~CaptionLayer();
    CaptionLayer(const CaptionLayer&) = delete;
    CaptionLayer& operator=(const CaptionLayer&) = delete;

    // Draws into the bound default framebuffer of width x height pixels.
    // Leaves the current ImGui context (the panel's) as it found it.
    // `rays` are drawn first, under the caption. `showCaption` false: the rays only.
    // `labels` (side by side) on dark boxes.
    void draw(const ViewCaption& caption, bool showCaption, const std::vector<OverlaySegment>& rays,
              const std::vector<OverlayLabel>& labels, int width, int height, float uiScale);

private:
    ImGuiContext* context_ = nullptr;
};

}  // namespace rl
