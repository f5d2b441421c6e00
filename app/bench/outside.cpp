#include "bench/outside.h"

#include "bench/textbook.h"
#include "core/file_io.h"
#include "shader/shader_library.h"

#include <sstream>

namespace rl::bench {

namespace fs = std::filesystem;

std::string outsideVariantName(const fs::path& file) { return "outside:" + file.stem().string(); }

namespace {
// Whether the first line that is neither blank nor a // comment is a #version line.
bool hasVersionLine(const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line.compare(first, 2, "//") == 0) continue;
        return line.compare(first, 8, "#version") == 0;
    }
    return false;
}
}  // namespace

ShaderProgram buildOutside(const fs::path& file, const Scene& scene) {
    const std::string text = readRegularFile(file, kOutsideShaderMaxBytes, "yardstick shader");
    const std::string shown = file.lexically_normal().string();
    AssembledSource fragment;
    if (!hasVersionLine(text)) {
        std::istringstream prelude(shaderPrelude({}));
        for (std::string line; std::getline(prelude, line);) fragment.append(line, {shown, 1});
    }
    std::istringstream lines(text);
    int number = 0;
    for (std::string line; std::getline(lines, line);) fragment.append(line, {shown, ++number});
    Implementation none;
    ShaderProgram program(assembleShader("fullscreen.vert", none, {}), fragment);
    setTextbookUniforms(program, scene);  // those it declares; the rest are ignored
    return program;
}

}  // namespace rl::bench
