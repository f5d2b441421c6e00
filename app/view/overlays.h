// What the window draws over the picture with ImGui: the help (H), the
// errors of shaders and scene files, the wipe's divider and labels, and a
// short-lived message (screenshot saved). None of it is in a screenshot of
// the picture (P); all of it is in a screenshot of the window (F12).
#pragma once

#include <string>
#include <vector>

namespace rl {

// Every key and mouse action, from key_bindings.h, centred on the window.
void drawHelpOverlay(bool& open);

// One box at the bottom of the window, red, with every current error
// (already formatted: "exercises: shaders/x.glsl:12: error: ...").
void drawErrorOverlay(const std::vector<std::string>& errors, float uiScale);

// The wipe's divider at `dividerX` window pixels and the two labels.
void drawWipeOverlay(float dividerX, float windowHeight, const std::string& left, const std::string& right,
                     float uiScale);

// A message at the top right, e.g. "saved raylab-20240131-142501.png".
void drawToast(const std::string& message, float uiScale);

}  // namespace rl
