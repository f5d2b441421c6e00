#include "bench/view_bench.h"

#include "bench/expert.h"
#include "bench/fastest_copy.h"
#include "bench/frame_clock.h"
#include "bench/textbook.h"

#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "gl/context.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <ostream>
#include <sstream>

namespace fs = std::filesystem;

namespace rl::bench {
namespace {

struct Entry {
    ViewBenchRow row;
    View view = View::Final;
    PictureProgram program;  // a sky program only for the still one
    std::function<PictureProgram()> build;  // another copy of it (Options::compiles)
    Rendering picture;
};

}  // namespace

std::vector<ViewBenchRow> runViewBench(const Options& options, std::ostream& log) {
    if (options.width < 1 || options.height < 1) throw Error("bench: the size must be at least 1x1");
    const std::string file = options.scenes.empty() ? (scenesDir() / "lecture.json").string() : options.scenes[0];
    LoadedScene loaded = loadSceneFile(file);
    for (const auto& w : loaded.warnings) log << "raylab: warning: " << w << "\n";
    Scene scene = loaded.scene;
    scene.render.width = options.width;
    scene.render.height = options.height;
    const fs::path implDir = options.implDir.empty() ? defaultImplementationDir() : options.implDir;
    if (!fs::is_directory(implDir)) throw Error("--impl: " + implDir.string() + " is not a directory");
    const Implementation impl{implDir, {}};
    const ImplementationFacts facts = implementationFacts(impl);

    auto context = createHeadlessContext(parseBackend(options.backend));
    Clock clock = options.clock;
    if (clock == Clock::Auto) clock = isSoftwareRasteriser(context->description()) ? Clock::Wall : Clock::Gpu;
    const std::string clockName = clock == Clock::Gpu ? "gpu" : clock == Clock::Wall ? "wall" : "cpu";
    log << "bench: view: " << fs::path(file).filename().string() << " at " << scene.render.width << "x"
        << scene.render.height << ", " << context->description() << ", clock " << clockName << "\n";

    // The picture and one teaching view (D), each with the generic program
    // (what the view drew with before issue #12) and the live one; for the
    // picture also `before`, the structure's program (Purpose::LiveView: what
    // the view draws with while a slider moves), and `live` is the still
    // picture's program (Purpose::LiveStill: the scene's numbers compiled in,
    // the camera a uniform; the same path as `raylab render`, for whatever
    // files are shown).
    std::vector<Entry> entries;
    for (View view : {View::Final, View::D})
        for (const char* program : {"generic", "before", "live"}) {
            if (view != View::Final && std::string(program) == "before") continue;
            Entry e;
            e.view = view;
            e.row.program = program;
            e.row.view = viewName(view);
            e.row.width = scene.render.width;
            e.row.height = scene.render.height;
            e.row.clock = clockName;
            const auto start = std::chrono::steady_clock::now();
            const Purpose purpose = e.row.program == "generic" || !isPictureView(view) ? Purpose::Generic
                                    : e.row.program == "before"                        ? Purpose::LiveView
                                                                                       : Purpose::LiveStill;
            e.build = [&impl, purpose, defines = definesFor(scene, facts, purpose)] {
                if (purpose == Purpose::LiveStill) return buildPictureProgram(impl, defines);
                PictureProgram p;
                p.program = buildRayTracer(impl, defines);
                return p;
            };
            e.program = e.build();
            e.row.compileMs = msSince(start);
            entries.push_back(std::move(e));
        }
    // The yardsticks, the picture only: the straightforward one
    // (bench/textbook.h; not in a student edition) and the expert
    // (bench/expert.h), the strongest.
    auto addYardstick = [&](const char* name, const std::function<ShaderProgram()>& build) {
        Entry e;
        e.row.program = name;
        e.row.view = viewName(View::Final);
        e.row.width = scene.render.width;
        e.row.height = scene.render.height;
        e.row.clock = clockName;
        const auto start = std::chrono::steady_clock::now();
        e.build = [build] {
            PictureProgram p;
            p.program = build();
            return p;
        };
        e.program = e.build();
        e.row.compileMs = msSince(start);
        entries.push_back(std::move(e));
    };
    if (textbookUnsupported().empty())
        addYardstick("textbook", [&] {
            ShaderProgram p = buildTextbook();
            setTextbookUniforms(p, scene);
            return p;
        });
    if (expertUnsupported(scene).empty()) addYardstick("expert", [&] { return buildExpert(scene); });

    GlRenderer renderer;
    renderer.setScene(scene);
    // A frame of `program` (the entry's, or another copy of it) as the live view draws it.
    auto drawProgram = [&](const Entry& e, const PictureProgram& program) {
        FrameSettings frame = frameFromScene(scene);
        frame.view = e.view;
        frame.radiance = false;  // the live view shows the display target alone
        return timeFrame(renderer, program, frame, clock);
    };
    auto drawOne = [&](Entry& e) { return drawProgram(e, e.program); };
    for (Entry& e : entries) {
        const auto start = std::chrono::steady_clock::now();
        FrameSettings first = frameFromScene(scene);
        first.view = e.view;
        renderer.drawChecked(e.program, first);  // as the view's first still frame: marked pixels get their program
        e.row.firstDrawMs = msSince(start);
        for (int k = 1; k < options.warmup; ++k) drawOne(e);
        // The fastest of Options::compiles copies, as in the error sweep.
        if (!keepFastestCopy(e.program, options.compiles, e.build,
                             [&](const PictureProgram& p) { return drawProgram(e, p); })
                 .empty())
            drawOne(e);  // the kept copy's picture, read below
        e.picture = renderer.readBack();
    }
    // Rounds, one frame of each program per round: a change of the machine's
    // load touches all of them alike.
    std::vector<std::vector<double>> times(entries.size());
    for (int round = 0; round < options.frames; ++round)
        for (std::size_t i = 0; i < entries.size(); ++i) times[i].push_back(drawOne(entries[i]));

    std::vector<ViewBenchRow> rows;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        Entry& e = entries[i];
        const bool yardstick = e.row.program == "textbook" || e.row.program == "expert";
        std::size_t g = 0;  // the generic program of the same view (the picture's for a yardstick)
        while (!(entries[g].row.program == "generic" && (yardstick ? entries[g].view == View::Final : entries[g].view == e.view))) ++g;
        const Entry& generic = entries[g];
        e.row.diff = compareRenderings(e.picture, generic.picture);
        e.row.frames = int(times[i].size());
        e.row.msMedian = median(times[i]);
        e.row.msMin = *std::min_element(times[i].begin(), times[i].end());
        e.row.msMax = *std::max_element(times[i].begin(), times[i].end());
        char line[256];
        std::snprintf(line, sizeof line, "bench: view %-7s %-7s %8.1f ms (min %.1f, max %.1f), compile %.0f ms\n",
                      e.row.program.c_str(), e.row.view.c_str(), e.row.msMedian, e.row.msMin, e.row.msMax,
                      e.row.compileMs);
        log << line;
        rows.push_back(e.row);
    }
    return rows;
}

std::string formatViewBench(const std::vector<ViewBenchRow>& rows) {
    std::ostringstream s;
    char line[256];
    std::snprintf(line, sizeof line, "%-8s %-6s %9s %10s %10s %10s %10s %8s %7s\n", "program", "view", "size",
                  "ms/frame", "min", "max", "compile", "1st draw", "max LSB");
    s << line;
    for (const ViewBenchRow& r : rows) {
        const std::string size = std::to_string(r.width) + "x" + std::to_string(r.height);
        std::snprintf(line, sizeof line, "%-8s %-6s %9s %10.1f %10.1f %10.1f %10.0f %8.0f %7d\n", r.program.c_str(),
                      r.view.c_str(), size.c_str(), r.msMedian, r.msMin, r.msMax, r.compileMs, r.firstDrawMs,
                      r.diff.maxLsb);
        s << line;
    }
    auto find = [&](const char* program, const std::string& view) {
        const auto at = std::find_if(rows.begin(), rows.end(),
                                     [&](const ViewBenchRow& r) { return r.program == program && r.view == view; });
        return at == rows.end() ? nullptr : &*at;
    };
    for (const ViewBenchRow& r : rows) {
        if (r.program != "live" || r.msMedian <= 0) continue;
        for (const char* other : {"generic", "before"})
            if (const ViewBenchRow* o = find(other, r.view)) {
                std::snprintf(line, sizeof line, "view %s: live %.2fx faster than %s (%.1f ms against %.1f ms)\n",
                              r.view.c_str(), o->msMedian / r.msMedian, other, r.msMedian, o->msMedian);
                s << line;
            }
    }
    const auto live = std::find_if(rows.begin(), rows.end(),
                                   [](const ViewBenchRow& r) { return r.program == "live" && r.view == "final"; });
    // Every ratio against the strongest yardstick of the run (the faster of
    // expert and textbook: the expert wherever it ran).
    const ViewBenchRow* strongest = nullptr;
    for (const ViewBenchRow& r : rows)
        if ((r.program == "textbook" || r.program == "expert") && (!strongest || r.msMedian < strongest->msMedian))
            strongest = &r;
    if (strongest && live != rows.end() && live->msMedian > 0) {
        std::snprintf(line, sizeof line,
                      "view final: live %.2fx the speed of the strongest yardstick, %s (%.1f ms against %.1f ms)\n",
                      strongest->msMedian / live->msMedian, strongest->program.c_str(), live->msMedian,
                      strongest->msMedian);
        s << line;
    }
    return s.str();
}

}  // namespace rl::bench
