#include "support/test_support.h"

#include "course/exercise_registry.h"

#include "gl/context.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"
#include "core/paths.h"
#include "shader/shader_library.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace rl::test {

CommandResult runRaylab(const std::string& args, const std::string& env) {
    return runShell((env.empty() ? "" : env + " ") + std::string(RAYLAB_BINARY) + " " + args);
}

CommandResult runShell(const std::string& command) {
    CommandResult result;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    int status = pclose(pipe);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::filesystem::path freshTempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("raylab_test_" + name + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path solutionsWithMutant(const std::filesystem::path& root, const std::string& exerciseFile,
                                          const std::filesystem::path& mutant) {
    namespace fs = std::filesystem;
    const fs::path dir = root / (fs::path(exerciseFile).stem().string() + "-" + mutant.stem().string());
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(sourceRoot() / "solutions"))
        if (entry.path().extension() == ".glsl") fs::copy_file(entry.path(), dir / entry.path().filename());
    fs::copy_file(mutant, dir / exerciseFile, fs::copy_options::overwrite_existing);
    return dir;
}

const char* const kBeyondScene = R"({
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 40},
  "render": {"width": 32, "height": 24, "max_bounces": 1, "spp": 1, "ambient": 0.03, "background": [0, 0, 0],
             "exposure": 1.0, "tonemap": "reinhard", "gamma": 2.2},
  "lights": [{"position": [0, 0, 2.5], "color": [1, 1, 1], "intensity": 10}],
  "spheres": [
    {"center": [0, 0, 0], "radius": 1, "material": {"albedo": [0.8, 0.8, 0.8], "roughness": 0.5, "metallic": 0, "ao": 1}},
    {"center": [0, 0, 6], "radius": 0.5, "material": {"albedo": [0.8, 0.2, 0.2], "roughness": 0.5, "metallic": 0, "ao": 1}}
  ]
})";

Rendering renderGl(const Scene& scene, const std::string& backend) {
    // One context per backend for the whole test process.
    static std::map<std::string, std::unique_ptr<GlContext>> contexts;
    auto& context = contexts[backend];
    if (!context) {
        contexts.clear();  // only one context may be current; drop the other backend's
        contexts[backend] = createHeadlessContext(parseBackend(backend));
    }
    ShaderProgram program = buildRayTracer(Implementation{solutionsDir(), {}}, definesFor(scene, ImplementationFacts{}, Purpose::EveryView));
    return renderOnce(program, scene, frameFromScene(scene));
}

std::string describe(const ImageDiff& d) {
    char text[256];
    std::snprintf(text, sizeof text, "off %.3f%% mean %.3f p99 %.1f max %d pfmMedianRel %.2g nonFinite %ld",
                  100 * d.offFraction, d.meanLsb, d.p99Lsb, d.maxLsb, d.pfmMedianRel, d.nonFinite);
    return text;
}

std::string shellQuoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

void copyRepositoryFiles(const std::filesystem::path& to) {
    namespace fs = std::filesystem;
    const std::string root = sourceRoot().string();
    CommandResult files = runShell("git -C " + shellQuoted(root) + " ls-files --cached --others --exclude-standard");
    if (files.status != 0) throw std::runtime_error("git ls-files in " + root + ": " + files.output);
    std::istringstream in(files.output);
    for (std::string rel; std::getline(in, rel);) {
        fs::path from = sourceRoot() / rel;
        std::error_code ec;
        if (!fs::is_regular_file(from, ec)) continue;  // deleted in the working tree
        fs::create_directories((to / rel).parent_path());
        fs::copy_file(from, to / rel, fs::copy_options::overwrite_existing);
        fs::permissions(to / rel, fs::status(from).permissions());
    }
}

std::vector<std::string> unitFileNames(const std::string& kind) {
    std::vector<std::string> names;
    for (const ExerciseInfo& e : allExercises()) {
        std::error_code ec;
        for (const auto& f : std::filesystem::directory_iterator(sourceRoot() / e.unitDir() / kind, ec))
            if (f.path().extension() == ".glsl") names.push_back(e.id + "--" + f.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::filesystem::path unitFilePath(const std::string& kind, const std::string& name) {
    std::size_t cut = name.find("--");
    std::string stem = name.substr(cut + 2);
    if (stem.size() < 5 || stem.substr(stem.size() - 5) != ".glsl") stem += ".glsl";
    return sourceRoot() / "course" / name.substr(0, cut) / kind / stem;
}

}  // namespace rl::test
