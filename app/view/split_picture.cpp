#include "view/split_picture.h"

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>

namespace rl {

SplitPicture::SplitPicture() {
    gl::GenFramebuffers(1, &upscaleFramebuffer_);
    gl::GenTextures(1, &upscaleTexture_);
}

SplitPicture::~SplitPicture() {
    gl::DeleteTextures(1, &upscaleTexture_);
    gl::DeleteFramebuffers(1, &upscaleFramebuffer_);
}

void SplitPicture::ensureUpscaleSource(int width, int height) const {
    if (width == upscaleWidth_ && height == upscaleHeight_) return;
    gl::BindTexture(GL_TEXTURE_2D, upscaleTexture_);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::BindFramebuffer(GL_FRAMEBUFFER, upscaleFramebuffer_);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, upscaleTexture_, 0);
    upscaleWidth_ = width;
    upscaleHeight_ = height;
}

void SplitPicture::keepForRefining() {
    if (width_ <= 0 || height_ <= 0 || sideBySide_) return;
    ensureUpscaleSource(width_, height_);
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, upscaleFramebuffer_);
    const int x0[2] = {0, split_}, x1[2] = {split_, width_};
    for (int i = 0; i < 2; ++i) {
        if (!drawn_[i] || x1[i] <= x0[i]) continue;
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, sides_[i].framebuffer());
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl::BlitFramebuffer(x0[i], 0, x1[i], height_, x0[i], 0, x1[i], height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void SplitPicture::setScene(const Scene& scene) {
    for (GlRenderer& side : sides_) side.setScene(scene);
}

void SplitPicture::renderSideBySide(const ShaderProgram* left, const ShaderProgram* right,
                                    const FrameSettings& frame, double leftFraction) {
    sideBySide_ = true;
    width_ = frame.width;
    height_ = frame.height;
    // Right of the panel (issue 26: it covered most of the left picture).
    offset_ = std::clamp(int(std::lround(leftFraction * frame.width)), 0, std::max(0, frame.width - 2));
    const int halfWidth = std::max(1, (frame.width - offset_) / 2);
    split_ = offset_ + halfWidth;
    // The whole picture in each half (issue 26: a centre crop showed neither
    // end of a material row): the window's aspect at half the width, so
    // half the height, letterboxed in present().
    halfHeight_ = std::max(1, int(std::lround(double(frame.height) * halfWidth / std::max(frame.width, 1))));
    const ShaderProgram* programs[2] = {left, right};
    for (int i = 0; i < 2; ++i) {
        FrameSettings half = frame;
        half.width = i == 0 ? halfWidth : std::max(1, frame.width - split_);
        half.height = halfHeight_;
        drawn_[i] = programs[i] != nullptr;
        if (drawn_[i]) sides_[i].draw(*programs[i], half);
    }
}

void SplitPicture::render(const ShaderProgram* left, const ShaderProgram* right, const FrameSettings& frame,
                          int splitX, int rows0, int rows1) {
    sideBySide_ = false;
    offset_ = 0;
    width_ = frame.width;
    height_ = frame.height;
    split_ = std::clamp(splitX, 0, width_);
    const ShaderProgram* programs[2] = {left, right};
    const int x0[2] = {0, split_}, x1[2] = {split_, width_};
    for (int i = 0; i < 2; ++i) {
        drawn_[i] = programs[i] && x1[i] > x0[i];
        if (!drawn_[i]) continue;
        gl::Enable(GL_SCISSOR_TEST);
        const int y0 = std::clamp(rows0, 0, height_), y1 = rows1 < 0 ? height_ : std::clamp(rows1, y0, height_);
        gl::Scissor(x0[i], y0, x1[i] - x0[i], y1 - y0);
        sides_[i].draw(*programs[i], frame);
        gl::Disable(GL_SCISSOR_TEST);
    }
}

void SplitPicture::render(PictureProgram& picture, const FrameSettings& frame, bool look, int rows0, int rows1) {
    sideBySide_ = false;
    offset_ = 0;
    width_ = frame.width;
    height_ = frame.height;
    split_ = width_;
    drawn_[0] = true;
    drawn_[1] = false;
    sides_[0].drawChecked(picture, frame, look, rows0, rows1);  // a marked pixel: its exact program, built once
}

void SplitPicture::present(int windowWidth, int windowHeight, const int covered[4], int pictureX0) const {
    pictureX0_ = sideBySide_ ? 0 : std::clamp(pictureX0, 0, std::max(0, windowWidth - 1));
    // The window less the covered rectangle, as up to four scissor boxes (GL
    // rows, bottom-up): right of it, left of it, above and below it. A blit
    // is cut by the scissor test, so each box copies its own pixels only.
    std::vector<std::array<int, 4>> boxes;  // x, y, width, height
    if (covered && covered[2] > covered[0] && covered[3] > covered[1]) {
        const int x0 = std::clamp(covered[0], 0, windowWidth), x1 = std::clamp(covered[2], 0, windowWidth);
        const int y0 = windowHeight - std::clamp(covered[3], 0, windowHeight),
                  y1 = windowHeight - std::clamp(covered[1], 0, windowHeight);
        boxes = {{x1, 0, windowWidth - x1, windowHeight}, {0, 0, x0, windowHeight}, {x0, y1, x1 - x0, windowHeight - y1},
                 {x0, 0, x1 - x0, y0}};
        boxes.erase(std::remove_if(boxes.begin(), boxes.end(), [](const auto& b) { return b[2] <= 0 || b[3] <= 0; }),
                    boxes.end());
    } else {
        boxes = {{0, 0, windowWidth, windowHeight}};
    }
    for (const auto& b : boxes) presentAll(windowWidth, windowHeight, boxes.size() > 1 ? b.data() : nullptr);
}

void SplitPicture::presentAll(int windowWidth, int windowHeight, const int* box) const {
    // The scissor box on the window's draws only (not on the 8-bit copy's).
    auto toWindow = [&] {
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        if (!box) return;
        gl::Enable(GL_SCISSOR_TEST);
        gl::Scissor(box[0], box[1], box[2], box[3]);
    };
    auto offWindow = [] { gl::Disable(GL_SCISSOR_TEST); };
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl::Viewport(0, 0, windowWidth, windowHeight);
    // Not side by side: the picture's columns in the window, right of the docked panel.
    const int px0 = pictureX0_, pictureWidth = windowWidth - px0;
    const int windowSplit = width_ > 0 ? px0 + int(std::lround(double(split_) * pictureWidth / width_)) : px0;
    // The blits below cover the window when every side with columns drew;
    // then a clear would be one more pass over every window pixel (on
    // llvmpipe at 1080p, a few ms of a 33 ms budget).
    const bool covered = !sideBySide_ && width_ > 0 && height_ > 0 && (drawn_[0] || windowSplit == px0) &&
                         (drawn_[1] || windowSplit == windowWidth);
    if (!covered) {
        toWindow();
        gl::ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        gl::Clear(GL_COLOR_BUFFER_BIT);
        offWindow();
    } else if (px0 > 0) {  // the columns left of the picture (the panel's), within the box
        const int bx0 = box ? box[0] : 0, bx1 = box ? std::min(box[0] + box[2], px0) : px0;
        if (bx1 > bx0) {
            gl::Enable(GL_SCISSOR_TEST);
            gl::Scissor(bx0, box ? box[1] : 0, bx1 - bx0, box ? box[3] : windowHeight);
            gl::ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            gl::Clear(GL_COLOR_BUFFER_BIT);
            gl::Disable(GL_SCISSOR_TEST);
        }
    }
    if (width_ == 0 || height_ == 0) return;
    const bool sameSize = width_ == (sideBySide_ ? windowWidth : pictureWidth) && height_ == windowHeight;
    if (sameSize && !sideBySide_ && refinedRows_ >= 0 && refinedRows_ < height_) {
        // Refining: the last reduced picture, upscaled from its 8-bit copy
        // (not refreshed: the targets are full size now), then the bands
        // done, 1:1, over it.
        toWindow();
        if (upscaleWidth_ > 0 && upscaleHeight_ > 0) {
            // Only the rows the bands have not reached (llvmpipe samples
            // every pixel of a scaled blit: the refined rows would be drawn twice).
            const double y0 = double(refinedRows_) * upscaleHeight_ / windowHeight;
            gl::BindFramebuffer(GL_READ_FRAMEBUFFER, upscaleFramebuffer_);
            gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
            gl::Enable(GL_SCISSOR_TEST);
            const int sx = box ? std::max(box[0], px0) : px0, sx1 = box ? std::min(box[0] + box[2], windowWidth) : windowWidth;
            const int sy = box ? std::max(box[1], refinedRows_) : refinedRows_,
                      sy1 = box ? std::min(box[1] + box[3], windowHeight) : windowHeight;
            if (sx1 > sx && sy1 > sy) {
                gl::Scissor(sx, sy, sx1 - sx, sy1 - sy);
                const int srcY0 = std::max(0, int(std::floor(y0)) - 1);  // a row below: the filter's neighbour
                const double dstY0 = double(srcY0) * windowHeight / upscaleHeight_;
                gl::BlitFramebuffer(0, srcY0, upscaleWidth_, upscaleHeight_, px0, int(std::lround(dstY0)), windowWidth,
                                    windowHeight, GL_COLOR_BUFFER_BIT, GL_LINEAR);
            }
            if (!box) gl::Disable(GL_SCISSOR_TEST);
            else gl::Scissor(box[0], box[1], box[2], box[3]);
        } else {
            gl::ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            gl::Clear(GL_COLOR_BUFFER_BIT);
        }
        for (int i = 0; i < 2; ++i) {
            const int x0 = i == 0 ? 0 : split_, x1 = i == 0 ? split_ : width_;
            if (!drawn_[i] || x1 <= x0 || refinedRows_ <= 0) continue;
            gl::BindFramebuffer(GL_READ_FRAMEBUFFER, sides_[i].framebuffer());
            gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
            gl::BlitFramebuffer(x0, 0, x1, refinedRows_, px0 + x0, 0, px0 + x1, refinedRows_, GL_COLOR_BUFFER_BIT,
                                GL_NEAREST);
        }
        offWindow();
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return;
    }
    const int src0[2] = {0, sideBySide_ ? 0 : split_},
              src1[2] = {sideBySide_ ? split_ - offset_ : split_, sideBySide_ ? std::max(1, width_ - split_) : width_};
    const int windowOffset = sideBySide_ ? (width_ > 0 ? int(std::lround(double(offset_) * windowWidth / width_)) : 0) : px0;
    const int dst0[2] = {windowOffset, windowSplit}, dst1[2] = {windowSplit, windowWidth};
    // Rows: the whole height, or side by side the letterboxed half picture,
    // centred (its top (windowHeight - rows) / 2 rows below the window's top).
    const int srcRows = sideBySide_ ? halfHeight_ : height_;
    const int dstRows = sideBySide_ ? std::max(1, int(std::lround(double(halfHeight_) * windowHeight / height_)))
                                    : windowHeight;
    const int dstY0 = windowHeight - dstRows - (windowHeight - dstRows) / 2, dstY1 = dstY0 + dstRows;
    if (!sameSize) ensureUpscaleSource(width_, height_);
    for (int i = 0; i < 2; ++i) {
        if (!drawn_[i]) continue;
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, sides_[i].framebuffer());
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);  // the display colour
        if (sameSize) {
            // Nearest at 1:1 keeps the pixels exactly as rendered (screenshots
            // match `raylab render`).
            toWindow();
            gl::BlitFramebuffer(src0[i], 0, src1[i], srcRows, dst0[i], dstY0, dst1[i], dstY1, GL_COLOR_BUFFER_BIT,
                                GL_NEAREST);
            offWindow();
            continue;
        }
        // Reduced: the columns to the 8-bit copy at the same size (cheap:
        // few pixels), then bilinear from it to the window (hides the blocks).
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, upscaleFramebuffer_);
        gl::BlitFramebuffer(src0[i], 0, src1[i], srcRows, src0[i], 0, src1[i], srcRows, GL_COLOR_BUFFER_BIT,
                            GL_NEAREST);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, upscaleFramebuffer_);
        toWindow();
        gl::BlitFramebuffer(src0[i], 0, src1[i], srcRows, dst0[i], dstY0, dst1[i], dstY1, GL_COLOR_BUFFER_BIT,
                            GL_LINEAR);
        offWindow();
    }
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace rl
