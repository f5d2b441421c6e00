// The browser edition's entry points, called from JavaScript (web/worker.js)
// through embind. Everything behind them is raylab's own C++: the checker
// (checks/), the renderer (render/), the CPU reference (reference/) and the
// trackball (camera/), compiled unchanged by scripts/build-web.sh. The
// repository's shaders/, solutions/ (where it has them: a student edition
// has none), exercises/ and scenes/ are embedded at
// /raylab, the working folder, so messages name files as `./raylab check`
// run from the repository root does ("exercises/07-fresnel.glsl:5: ...").
// The student's files are written to /raylab/exercises/ before each call.
#include "camera/trackball.h"
#include "checks/checker.h"
#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/image.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "render/gl_renderer.h"
#include "render/scene_uniforms.h"
#include "render/define_table.h"
#include "shader/shader_library.h"

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <sys/stat.h>
#include <unistd.h>

namespace rl::web {
namespace {

using nlohmann::json;

const std::vector<CheckScene>& checkScenes() {
    static const std::vector<CheckScene> scenes = makeCheckScenes();
    return scenes;
}

CheckOptions checkOptions() {
    CheckOptions options;
    options.implDir = exercisesDir();
    options.outputDir = "check-output";  // relative to /raylab, as the native default
    options.isolate = false;  // no fork in a browser: the page's Worker is the isolation (docs/web.md)
    return options;
}

// ---- check ---------------------------------------------------------------------------------

// A student edition (no solutions/ embedded): the probes of all ten, the
// first pass of checkWithOwnFiles(), kept while the ten files stay as they
// were, so that checking all ten one by one runs them once.
const std::map<int, ExerciseReport>& firstPass(const CheckOptions& options) {
    static std::string files;
    static std::map<int, ExerciseReport> reports;
    std::string now;
    for (const ExerciseInfo& e : allExercises()) {
        std::ifstream in(options.implDir / e.file(), std::ios::binary);
        now += e.file() + '\0' + std::string(std::istreambuf_iterator<char>(in), {}) + '\0';
    }
    if (now != files || reports.empty()) {
        reports = checkProbesOfAll(options, checkScenes());
        files = now;
    }
    return reports;
}

std::string checkOne(int number) {
    const ExerciseInfo& exercise = findExercise(std::to_string(number));
    ExerciseReport report;
    try {
        const CheckOptions options = checkOptions();
        report = hasSolutions() ? checkExercise(exercise, options, checkScenes())
                                : checkWithOwnFiles(exercise, options, checkScenes(), firstPass(options));
    } catch (const std::exception& e) {
        report.number = number;
        report.id = exercise.id;
        report.status = CheckStatus::Crashed;
        report.message = e.what();
    }
    json out = toJson(report);
    out["text"] = formatReport(report, false);
    return out.dump();
}

std::string checkTogetherJson() {
    std::optional<ExerciseReport> report = checkTogether(checkOptions());
    if (!report) return "null";
    json out = toJson(*report);
    out["text"] = formatReport(*report, false);
    return out.dump();
}

// ---- the live picture ------------------------------------------------------------------------

struct Live {
    std::unique_ptr<GlContext> context;
    Scene scene;
    std::unique_ptr<Trackball> trackball;
    std::unique_ptr<GlRenderer> renderer;
    std::unique_ptr<ShaderProgram> program;  // the last program that compiled (kept on a compile error)
    std::vector<std::uint8_t> rgba;
};
Live& live() {
    static Live l;
    return l;
}

// Loads a bundled scene ("lecture.json", or "" for the default scene).
std::string setScene(const std::string& name, int width, int height) {
    try {
        Live& l = live();
        if (!l.context) l.context = createHeadlessContext(Backend::Auto);
        l.scene = name.empty() ? defaultScene() : loadSceneFile((scenesDir() / name).string()).scene;
        l.scene.render.width = width;
        l.scene.render.height = height;
        l.trackball = std::make_unique<Trackball>(l.scene.camera, width, height);
        if (!l.renderer) l.renderer = std::make_unique<GlRenderer>();
        l.renderer->setScene(l.scene);
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

// Builds the ray tracer from /raylab/exercises as the live view does (every
// view compiled in). On an error the last good program stays; the error is
// returned, naming the student's file and line.
std::string compileLive() {
    Live& l = live();
    try {
        if (!l.context) l.context = createHeadlessContext(Backend::Auto);
        Implementation impl{exercisesDir(), {}};
        l.program = std::make_unique<ShaderProgram>(
            buildRayTracer(impl, definesFor(l.scene, ImplementationFacts{}, Purpose::EveryView)));
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

// One frame of the current view; the display colours as RGBA bytes, rows top
// to bottom (a view of the module's memory, valid until the next call).
emscripten::val renderLive(const std::string& viewName) {
    Live& l = live();
    if (!l.program || !l.trackball) return emscripten::val::null();
    FrameSettings frame = frameFromScene(l.scene);
    frame.cameraToWorld = l.trackball->cameraToWorldD();
    frame.view = parseView(viewName, frame.viewBounce);
    l.renderer->draw(*l.program, frame);
    Rendering r = l.renderer->readBack();
    l.rgba.assign(std::size_t(r.display.width) * r.display.height * 4, 255);
    for (std::size_t i = 0; i < std::size_t(r.display.width) * r.display.height; ++i)
        for (int c = 0; c < 3; ++c) l.rgba[4 * i + c] = r.display.rgb[3 * i + c];
    return emscripten::val(emscripten::typed_memory_view(l.rgba.size(), l.rgba.data()));
}

void trackballBegin(double x, double y, int mode) {
    if (live().trackball) live().trackball->beginDrag({x, y}, Trackball::Mode(mode));
}
void trackballDrag(double x, double y) {
    if (live().trackball && live().trackball->dragging()) live().trackball->drag({x, y});
}
void trackballEnd() {
    if (live().trackball) live().trackball->endDrag();
}
void trackballZoom(double steps) {
    if (live().trackball) live().trackball->zoom(steps);
}
void trackballReset() {
    if (live().trackball) live().trackball->reset();
}

// The current live frame against the CPU reference at the trackball's
// camera: the agreement the checker's images are judged by (core/image.h).
std::string compareLiveWithReference() {
    Live& l = live();
    if (!l.program || !l.trackball) return "{}";
    Scene scene = l.scene;
    scene.camera = l.trackball->camera();
    FrameSettings frame = frameFromScene(l.scene);
    frame.cameraToWorld = l.trackball->cameraToWorldD();
    l.renderer->draw(*l.program, frame);
    Rendering got = l.renderer->readBack();
    Rendering expected = ref::renderCpu(scene);
    ImageDiff d = compareRenderings(got, expected);
    return json{{"off_fraction", d.offFraction}, {"mean_lsb", d.meanLsb}, {"max_lsb", d.maxLsb},
                {"non_finite", d.nonFinite}, {"width", got.display.width}, {"height", got.display.height}}
        .dump();
}

std::string contextDescription() {
    try {
        return createHeadlessContext(Backend::Auto)->description();
    } catch (const std::exception& e) {
        return std::string("no context: ") + e.what();
    }
}

// The exercises, in order: number, id, file, title, handout and whether it is optional (a bonus).
std::string exerciseList() {
    json list = json::array();
    for (const ExerciseInfo& e : allExercises())
        list.push_back({{"number", e.number}, {"id", e.id}, {"file", e.file()}, {"title", e.title},
                        {"handout", e.handout()}, {"optional", e.optional}});
    return list.dump();
}

}  // namespace
}  // namespace rl::web

int main() {
    // Emscripten starts with umask 0777: every file raylab writes (the check's
    // pictures) would get mode 000 and the page could not read it back.
    umask(022);
    // The working folder is the embedded repository: relative paths read as natively.
    if (chdir(rl::sourceRoot().c_str()) != 0) return 1;
    return 0;
}

EMSCRIPTEN_BINDINGS(raylab) {
    using namespace rl::web;
    emscripten::function("checkOne", &checkOne);
    emscripten::function("checkTogether", &checkTogetherJson);
    emscripten::function("setScene", &setScene);
    emscripten::function("compileLive", &compileLive);
    emscripten::function("renderLive", &renderLive);
    emscripten::function("trackballBegin", &trackballBegin);
    emscripten::function("trackballDrag", &trackballDrag);
    emscripten::function("trackballEnd", &trackballEnd);
    emscripten::function("trackballZoom", &trackballZoom);
    emscripten::function("trackballReset", &trackballReset);
    emscripten::function("compareLiveWithReference", &compareLiveWithReference);
    emscripten::function("contextDescription", &contextDescription);
    emscripten::function("exerciseList", &exerciseList);
}
