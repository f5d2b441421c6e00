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

// Where the label goes (window units): beside the pixel, right and below,
// else right and above, left and below, left and above: the first of them
// inside the window (less a margin) and clear of every box of `avoid`; where
// none is, the one that overlaps least, moved inside the window. `width` and
// `height`: the label's size.
LayoutRect askedPixelLabelBox(float x, float y, float width, float height, float windowWidth, float windowHeight,
                              float uiScale, const std::vector<LayoutRect>& avoid);

// Draws the ring and the label (ImGui, window units); the text is shrunk down
// to UI scale 1 and then wrapped where a line does not fit the window.
// Returns the label's box (window units).
LayoutRect drawAskedPixelLabel(const AskedPixelLabel& label, float uiScale, const std::vector<LayoutRect>& avoid);

}  // namespace rl
