// The ray-traced picture of the window: one implementation, or two side by
// side with a wipe (--compare). Each side renders into its own GlRenderer
// target, only the pixels on its side of the divider (scissor), so a wipe
// costs one picture, not two; present() blits both halves to the window,
// upscaled when the picture was rendered at a lower resolution.
#pragma once

#include "render/gl_renderer.h"

namespace rl {

class SplitPicture {
public:
    // Spheres and lights of both sides.
    void setScene(const Scene& scene);

    // `frame.width` x `frame.height` is the render size. `left` draws the
    // columns [0, splitX), `right` the columns [splitX, width); a null
    // program (none has built yet) leaves its side black.
    // Rows [rows0, rows1) only (from the bottom; rows1 < 0: all): one band
    // of a picture that refines over several frames (setRefinedRows).
    void render(const ShaderProgram* left, const ShaderProgram* right, const FrameSettings& frame, int splitX,
                int rows0 = 0, int rows1 = -1);
    // While a full-size picture comes in by bands: present() shows its
    // rows [0, rows) over the last reduced picture, upscaled (kept from the
    // last present at a reduced size); -1: the picture alone.
    void setRefinedRows(int rows) { refinedRows_ = rows; }
    // Before the first band over a picture already at full size (drawn by
    // the structure's program while the hand moved): that picture becomes
    // the one the bands come in over.
    void keepForRefining();
    // One picture over the whole frame, with its sky tiles where it has a sky
    // program; `look`: read the frame back for marked pixels
    // (GlRenderer::drawChecked: the view looks when the camera rests).
    // Rows [rows0, rows1) as above: a band of the still (GlRenderer::draw's
    // bands: the sky tiles and the exact redraw keep to it too).
    void render(PictureProgram& picture, const FrameSettings& frame, bool look, int rows0 = 0, int rows1 = -1);

    // Side by side: two whole pictures, the same camera, each half of the
    // columns right of leftFraction of the width (the panel's; the right one
    // takes the odd column) and as tall as the window's aspect gives;
    // present() puts them there, centred vertically.
    void renderSideBySide(const ShaderProgram* left, const ShaderProgram* right, const FrameSettings& frame,
                          double leftFraction = 0);  // the pictures start leftFraction of the width from the left
    bool sideBySide() const { return sideBySide_; }

    // Copies the last render to the default framebuffer's back buffer,
    // stretched to windowWidth x windowHeight (bilinear when upscaling).
    // `covered` (window pixels, origin top-left): an opaque rectangle drawn
    // over the picture afterwards (the panel), whose pixels are not copied.
    // `pictureX0`: the picture (not side by side) goes to the window's
    // columns [pictureX0, windowWidth), right of the docked panel; the
    // columns left of it are cleared.
    void present(int windowWidth, int windowHeight, const int covered[4] = nullptr, int pictureX0 = 0) const;

    int width() const { return width_; }
    int height() const { return height_; }
    // Side by side: each half is the whole picture scaled into its half
    // (same aspect as the window, letterboxed), this many rows tall.
    int halfHeight() const { return halfHeight_; }

    SplitPicture();
    ~SplitPicture();
    SplitPicture(const SplitPicture&) = delete;
    SplitPicture& operator=(const SplitPicture&) = delete;

private:
    // A reduced picture is upscaled from an 8-bit copy of it: llvmpipe
    // filters an RGBA8 texture on its fast path, while filtering the RGBA32F
    // targets directly took 30 to 75 ms at 1920x1080 on two cores (more than
    // the whole frame budget), against a render of 2 ms at the lowest scale.
    void ensureUpscaleSource(int width, int height) const;
    void presentAll(int windowWidth, int windowHeight, const int* box) const;  // present() within `box` (GL scissor), or all
    GLuint upscaleFramebuffer_ = 0, upscaleTexture_ = 0;
    mutable int upscaleWidth_ = 0, upscaleHeight_ = 0;  // allocated by present()
    GlRenderer sides_[2];
    bool drawn_[2] = {false, false};
    int width_ = 0, height_ = 0, split_ = 0;
    int offset_ = 0;  // side by side: the columns left of the pictures (the panel's)
    int halfHeight_ = 0;
    bool sideBySide_ = false;
    int refinedRows_ = -1;
    mutable int pictureX0_ = 0;  // present()'s
};

}  // namespace rl
