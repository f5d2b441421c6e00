// The asked pixel's answer on the picture (issue 37): after a Ctrl+click,
// a label beside the pixel with the first differing quantity, its function
// and exercise, the program's value and the model's (or "agrees with the
// model"), at every UI scale; a small ring marks the pixel. The lines come
// from the pixel debugger (render/pixel_debugger.h, pixelDebugLabel()); the
// window places the label with askedPixelLabelBox() clear of its widgets and
// reports the box to the layout report as "asked pixel label".
#pragma once

#include "view/layout_report.h"

#include <string>
#include <vector>

namespace rl {

struct AskedPixelLabel {
    float x = 0, y = 0;               // the pixel's centre, window units from the top left
    std::vector<std::string> lines;   // pixelDebugLabel(): at most three
    bool agrees = false;              // the pixel agrees with the model: drawn green, else red
};

// Where a label of `width` x `height` goes (window units): inside the window
// (less a margin), the place that covers the least of `avoid` and of the
// pixel, and of those the nearest to the pixel (beside it where there is
// room: right and below first). `overlap`: the area it still covers (0: free).
LayoutRect askedPixelLabelBox(float x, float y, float width, float height, float windowWidth, float windowHeight,
                              float uiScale, const std::vector<LayoutRect>& avoid, float* overlap = nullptr);

// Draws the ring and the label (ImGui, window units): at the UI scale where
// a free place fits it, else smaller (down to UI scale 1), else wrapped
// narrower (down to 14 characters a line).
// Returns the label's box (window units).
LayoutRect drawAskedPixelLabel(const AskedPixelLabel& label, float uiScale, const std::vector<LayoutRect>& avoid);

}  // namespace rl
