#include "view/screenshot.h"

#include "gl/gl_api.h"

#include <ctime>
#include <filesystem>
#include <vector>

namespace rl {

DisplayImage readWindowPixels(int width, int height) {
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl::ReadBuffer(GL_BACK);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    DisplayImage out{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    for (int y = 0; y < height; ++y) {  // GL rows start at the bottom
        const std::uint8_t* row = &rgba[std::size_t(height - 1 - y) * width * 4];
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) out.at(x, y)[c] = row[4 * x + c];
    }
    return out;
}

std::string timestampedScreenshotName() {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::string base = std::string("raylab-") + stamp;
    std::string name = base + ".png";
    for (int n = 2; std::filesystem::exists(name); ++n) name = base + "-" + std::to_string(n) + ".png";
    return name;
}

}  // namespace rl
