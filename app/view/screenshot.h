// Screenshots of the window: what the back buffer holds at the moment of the
// call (before or after the panel is drawn, as the caller chooses).
#pragma once

#include "core/image.h"

#include <string>

namespace rl {

// Reads the default framebuffer's back buffer (width x height pixels); rows
// top to bottom, as PNG stores them.
DisplayImage readWindowPixels(int width, int height);

// "raylab-20240131-142501.png" in the working directory; "-2", "-3", ...
// appended when a file of that name exists (two shots in one second).
std::string timestampedScreenshotName();

}  // namespace rl
