// Screen tiles whose camera rays can hit no sphere. On llvmpipe every pixel
// of a program pays for all of its code, whatever the pixel needs (an `if`
// only masks lanes), so a pixel that sees only the background costs as much
// as one that sees a sphere. The host, in double, finds the tiles where no
// camera ray can reach any sphere, and `raylab render` draws them with a
// program that has no sphere (skyProgramDefines(), render/define_table.h):
// the same code, so the same pixels, at a fraction of the cost
// (docs/performance.md, "Sky tiles").
#pragma once

#include "core/scene.h"
#include "render/scene_uniforms.h"

#include <vector>

namespace rl {

// A rectangle of pixels in GL window coordinates (x right, y up from the bottom).
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct SkyTiles {
    std::vector<PixelRect> sky;    // no camera ray through these pixels can hit a sphere
    std::vector<PixelRect> scene;  // the rest; together they cover the frame once
    double skyShare = 0;           // of the frame's pixels
};

// Conservative: a tile is sky only when the bounding cone of its rays misses
// every sphere by a margin far above float32's rounding of a camera ray.
// Tiles of `tile` x `tile` pixels, merged into rectangles row by row.
SkyTiles skyTiles(const Scene& scene, const FrameSettings& frame, int tile = 16);

// Rectangles covering the tiles marked in `chosen` (row-major, the bottom row
// first, `columns` tiles of `tile` x `tile` pixels a row, clipped to the
// frame): runs along each row, joined across rows where their extent agrees.
std::vector<PixelRect> tileRects(const std::vector<bool>& chosen, int columns, int tile, int width, int height);

}  // namespace rl
