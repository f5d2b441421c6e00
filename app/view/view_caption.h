// What the picture says about itself: the caption of the teaching view (its
// name, the model variant in use, the formula in the handouts' notation) and
// the colour bar that gives its grey levels a value. Pure data and layout,
// no GL: caption_layer.h draws it, the window tests read it back.
#pragma once

#include "core/scene.h"
#include "render/scene_uniforms.h"

#include <string>
#include <vector>

namespace rl {

// A grey ramp from black (position 0) to white (position 1): every teaching
// view writes its mapped value as the grey level itself (the radiance views
// through the display step), so a tick's position IS the pixel value of the
// quantity it names.
struct ColourScale {
    struct Tick {
        double position;   // 0..1 along the bar
        std::string text;  // "0.04"
    };
    std::string label;  // "log scale: 0.01 .. 1"
    std::vector<Tick> ticks;
    // A view of a few values (the shadow view: 0 or 1) gets one swatch per
    // tick instead of a ramp: a gradient would show greys it never draws.
    bool swatches = false;
};

struct ViewCaption {
    std::string title;    // "3  F(v.h): Fresnel of the key light's highlight"
    std::string model;    // "F: Schlick (the scene's model)"
    std::string formula;  // "F = F0 + (1 - F0) (1 - VoH)^5"
    ColourScale scale;
};

// `model`: the model the program shows (the scene's, or --compare-model's).
ViewCaption viewCaption(View view, int bounce, const Scene& scene, const ShadingModel& model);

// The mapping the shader applies before writing the grey level (views.glsl):
//   D: D / (1 + D);  F views: log10(F) / 2 + 1 (0.01 .. 1);  G, n.l, shadow: the value;
//   normals: n * 0.5 + 0.5;  radiance views: the display step of the scene
//   (-1 in a student edition, which has no CPU reference: no tick there).
double scalePosition(View view, double value, const RenderSettings& render);

// Where the caption box and the colour bar sit, in framebuffer pixels (origin
// top-left): the bottom-right corner, clear of the panel (top-left), the
// errors (bottom-left) and the wipe labels (top). Everything scales with the
// UI scale; the bar never leaves a small window.
struct CaptionLayout {
    float scale = 1;       // the UI scale
    float margin = 10;     // from the window's edges
    float pad = 6;         // inside the box
    float fontSize = 13;   // ImGui's default font, scaled
    float barX = 0, barY = 0, barWidth = 0, barHeight = 0;  // the ramp itself
    float right = 0, bottom = 0;                           // the box's bottom-right corner
    float textWidth = 0;   // the wrap width of the caption's lines
};
CaptionLayout captionLayout(int width, int height, float uiScale);

// A name over the picture (side by side), top-left corner at (x, y) framebuffer pixels;
// `wrap` > 0: its box is at most that wide, the text wrapped onto more lines.
struct OverlayLabel {
    float x, y;
    std::string text;
    float wrap = 0;
};

// A line drawn over the picture (the asked pixel's rays), framebuffer pixels.
struct OverlaySegment {
    float x0, y0, x1, y1;
    unsigned colour;  // ImGui's IM_COL32 (ABGR)
};

}  // namespace rl
