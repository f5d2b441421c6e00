// Option values shared by the commands: sizes and numeric validators (see commands.h).
#include "commands/commands.h"

#include "core/error.h"
#include "core/message.h"
#include "core/scene.h"
#include "core/scene_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace rl {

namespace {

// The whole text as a finite number, or false.
bool parseNumber(const std::string& text, double& value) {
    // Decimal only: strtod would also take "0x10", "inf", "nan" and leading blanks.
    if (text.empty() || text.size() > 64 || text.find_first_not_of("0123456789+-.eE") != std::string::npos)
        return false;
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    return *end == '\0' && errno == 0 && std::isfinite(value);
}

std::string numberText(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

std::string rangeText(double min, double max) { return numberText(min) + " to " + numberText(max); }

}  // namespace

std::string sizeProblem(const std::string& text, Size& size) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    long long pixels = 0;
    // At most 5 digits a side: sscanf's %d overflows silently ("4294967328" read as 32).
    const std::size_t cross = text.find_first_of("xX");
    const bool digitsOnly = cross != std::string::npos && cross >= 1 && cross <= 5 && text.size() - cross - 1 >= 1 &&
                            text.size() - cross - 1 <= 5 &&
                            text.find_first_not_of("0123456789", 0) == cross &&
                            text.find_first_not_of("0123456789", cross + 1) == std::string::npos;
    if (!digitsOnly || std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 ||
        (x != 'x' && x != 'X') || w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide ||
        !std::isdigit(static_cast<unsigned char>(text[0])))
        return "expected WIDTHxHEIGHT between 1x1 and 16384x16384, e.g. 640x480, not " + quotedValue(text);
    pixels = (long long)w * h;
    if (pixels > kMaxPixels)
        return text + " is " + std::to_string(pixels) + " pixels, more than the limit of " +
               std::to_string(kMaxPixels) + " (8192x8192)";
    size = {w, h};
    return "";
}

Size parseSize(const std::string& text) {
    Size size;
    std::string problem = sizeProblem(text, size);
    if (!problem.empty()) throw Error("--size: " + problem);
    return size;
}

Scene sceneForCommand(const std::string& path, const std::string& size) {
    LoadedScene loaded = path.empty() ? LoadedScene{defaultScene(), {}} : loadSceneFile(path);
    for (const auto& w : loaded.warnings) std::cerr << "raylab: warning: " << w << "\n";
    Scene scene = loaded.scene;
    if (!size.empty()) {
        Size s = parseSize(size);
        scene.render.width = s.width;
        scene.render.height = s.height;
    }
    return scene;
}

CLI::Validator sizeValue() {
    return CLI::Validator(
        [](std::string& text) {
            Size size;
            return sizeProblem(text, size);
        },
        "WIDTHxHEIGHT");
}

CLI::Validator wholeNumberIn(long long min, long long max) {
    return CLI::Validator(
        [min, max](std::string& text) -> std::string {
            double v = 0;
            if (!parseNumber(text, v) || v != std::floor(v) || v < double(min) || v > double(max))
                return "must be a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
                       ", not " + quotedValue(text);
            return "";
        },
        "INT in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

CLI::Validator squareNumberIn(long long min, long long max) {
    return CLI::Validator(
        [min, max](std::string& text) -> std::string {
            double v = 0;
            long long n = 0;
            if (parseNumber(text, v) && v == std::floor(v) && v >= double(min) && v <= double(max))
                n = std::llround(std::sqrt(v));
            if (n == 0 || double(n * n) != v)
                return "must be a square number from " + std::to_string(min) + " to " + std::to_string(max) +
                       " (1, 4, 9, 16, ...), not " + quotedValue(text);
            return "";
        },
        "SQUARE in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

CLI::Validator secondsIn(double minExclusive, double max) {
    return CLI::Validator(
        [minExclusive, max](std::string& text) -> std::string {
            double v = 0;
            if (!parseNumber(text, v) || !(v > minExclusive) || v > max)
                return "must be a number of seconds more than " + numberText(minExclusive) + " and at most " +
                       numberText(max) + ", not " + quotedValue(text);
            return "";
        },
        "SECONDS");
}

CLI::Validator numberIn(double min, double max) {
    return CLI::Validator(
        [min, max](std::string& text) -> std::string {
            double v = 0;
            if (!parseNumber(text, v) || v < min || v > max)
                return "must be a number from " + rangeText(min, max) + ", not " + quotedValue(text);
            return "";
        },
        "NUMBER in [" + rangeText(min, max) + "]");
}

CLI::Validator notEmpty() {
    return CLI::Validator(
        [](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; }, "TEXT");
}

}  // namespace rl
