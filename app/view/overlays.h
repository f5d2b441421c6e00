// What the window draws over the picture with ImGui: the help (H), the
// errors of shaders and scene files, the wipe's divider and labels, and a
// short-lived message (screenshot saved). None of it is in a screenshot of
// the picture (P); all of it is in a screenshot of the window (F12).
#pragma once

#include "view/layout_report.h"

#include <string>
#include <vector>

namespace rl {

// Every key and mouse action, from key_bindings.h, at the UI scale, opaque,
// inside `area` (window units; empty: the window less the margins): as many
// column pairs as fit unwrapped, else one pair with the descriptions
// wrapped, and in pages where the rows do not fit the height (`page` of
// `pages`, H turns them). Nothing scrolls or is cut. Returns the box drawn
// and the rows' extent (window units), empty when closed.
struct HelpRects {
    LayoutRect box, rows;
};
HelpRects drawHelpOverlay(bool& open, int& page, int& pages, float uiScale, LayoutRect area = {});

// One box, red, with every current error (already formatted:
// "exercises: shaders/x.glsl:12: error: ..."), inside `area` (window units):
// at its bottom-left corner, or its top-left with `atTop`; taller content
// scrolls. An empty area: the whole window less the margins. Returns the
// box drawn (window units), empty when there is no error.
LayoutRect drawErrorOverlay(const std::vector<std::string>& errors, float uiScale, LayoutRect area = {},
                            bool atTop = false);

// The wipe's two names, top-left corners in window units, placed by
// wipeLabelBoxes(): beside the divider at the top, right of `minX` (the
// panel's edge); a name that does not fit beside it goes to the next row,
// at the edge of its side.
struct WipeLabels {
    LayoutRect left, right;  // their dark boxes
};
WipeLabels wipeLabelBoxes(float dividerX, float windowWidth, float minX, float leftWidth, float rightWidth,
                          float textHeight, float uiScale);

// The divider's pieces at `dividerX`: the whole height less where it would
// cross a box of `avoid` (the caption, the errors, the names, the panel).
std::vector<LayoutRect> dividerPieces(float dividerX, float windowHeight, float uiScale,
                                      const std::vector<LayoutRect>& avoid);

// Draws the divider's pieces and the two names in their boxes (window units).
void drawWipeOverlay(const std::vector<LayoutRect>& divider, const WipeLabels& boxes, const std::string& left,
                     const std::string& right, float uiScale);

// A message at the top right, e.g. "saved raylab-20240131-142501.png",
// its top `top` window units down (below the wipe's names or a caption
// there; 0: the margin), at most `maxWidth` wide (0: the window less the
// margins; longer text wraps). Returns its box (window units).
LayoutRect drawToast(const std::string& message, float uiScale, float top = 0, float maxWidth = 0);

}  // namespace rl
