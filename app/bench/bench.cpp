#include "bench/bench.h"

#include "bench/frame_clock.h"
#include "bench/pareto.h"
#include "bench/expert.h"
#include "bench/fastest_copy.h"
#include "bench/outside.h"
#include "bench/textbook.h"
#include "core/error.h"
#include "core/message.h"
#include "core/file_io.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "course/exercise_registry.h"
#include "gl/context.h"
#include "reference/cpu_reference.h"
#include "render/gl_renderer.h"
#include "render/define_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

namespace rl::bench {

namespace fs = std::filesystem;

const std::vector<std::string>& sweepNames() {
    static const std::vector<std::string> names = {"modes", "layers", "bounces", "spp", "resolution", "models", "strategies", "environment"};
    return names;
}

std::string modeName(bool specialised, bool picture) {
    if (specialised) return picture ? "specialised" : "specialised-full";
    return picture ? "generic-picture" : "generic";
}

namespace {

bool wanted(const Options& o, const std::string& sweep) { return o.sweeps.empty() || o.sweeps.count(sweep) > 0; }

struct ModelVariant {
    const char* name;
    ShadingModel model;
};
std::vector<ModelVariant> modelVariants() {
    std::vector<ModelVariant> out;
    ShadingModel m;
    m.distribution = DistributionModel::Beckmann;
    out.push_back({"model:beckmann", m});
    m = {};
    m.geometry = GeometryModel::SmithGGXSeparable;
    out.push_back({"model:smith-ggx", m});
    m = {};
    m.geometry = GeometryModel::SmithGGXCorrelated;
    out.push_back({"model:smith-ggx-correlated", m});
    m = {};
    m.fresnel = FresnelModel::Dielectric;
    out.push_back({"model:fresnel-dielectric", m});
    m = {};
    m.fresnel = FresnelModel::Conductor;
    out.push_back({"model:fresnel-conductor", m});
    m = {};
    m.diffuse = DiffuseModel::Burley;
    out.push_back({"model:burley", m});
    m = {};
    m.blinnPhong = true;
    out.push_back({"model:blinn-phong", m});
    return out;
}



std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string sceneName(const std::string& path) { return fs::path(path).stem().string(); }

}  // namespace

std::vector<Variant> makeVariants(const Scene& scene, const Options& options) {
    std::vector<Variant> out;
    auto add = [&](std::string name, std::string sweep, bool specialised, Scene s, bool picture = true) {
        Variant v;
        v.name = std::move(name);
        v.sweep = std::move(sweep);
        v.specialised = specialised;
        v.picture = picture;
        v.scene = std::move(s);
        out.push_back(std::move(v));
        return &out.back();
    };
    const RenderSettings& r = scene.render;

    if (wanted(options, "modes")) {
        Variant* textbook = add("textbook", "modes", false, scene, false);
        textbook->textbook = true;
        textbook->skipReason = textbookUnsupported();
        Variant* expert = add("expert", "modes", false, scene, false);
        expert->expert = true;
        expert->skipReason = expertUnsupported(scene);
        for (const fs::path& file : options.yardsticks) add(outsideVariantName(file), "modes", false, scene, false)->outside = file;
        add("generic", "modes", false, scene, false);
        add("generic-picture", "modes", false, scene, true);
        add("specialised-full", "modes", true, scene, false);
        add("specialised", "modes", true, scene, true);
        for (const fs::path& dir : options.alsoImpls) {
            Variant* other = add("specialised:" + dir.filename().string(), "modes", true, scene, true);
            for (const ExerciseInfo& e : allExercises()) other->overrides[e.file()] = dir / e.file();
        }
    }
    if (wanted(options, "layers")) {
        // The course's picture program with one of its layers taken out
        // again, one at a time: what each costs or saves
        // (docs/performance.md). The layers are the define table's rows
        // marked BenchLayer::Without (render/define_table.h), in its order;
        // a row that is a threshold's choice (benchWith) is measured on its
        // other side too, so that the bench shows whether the threshold is
        // right for this scene.
        const ShaderDefines all =
            definesFor(scene, implementationFacts(Implementation{defaultImplementationDir(), {}}), Purpose::Picture);
        std::vector<std::string> with;
        for (const DefineRow& row : defineTable()) {
            if (row.layer != BenchLayer::Without) continue;
            if (all.count(row.name)) {
                add("without:" + glslName(row), "layers", true, scene)->withoutDefines.push_back(row.name);
            } else if (row.benchWith && row.benchWith(scene)) {
                with.push_back(row.name);
            }
        }
        for (const std::string& name : with) add("with:" + name, "layers", true, scene)->withDefines[name] = "1";
    }
    if (wanted(options, "bounces")) {
        for (int b : {0, 1, 2, 3, 4}) {
            if (b == r.maxBounces && wanted(options, "modes")) continue;  // that is the "specialised" row
            Scene s = scene;
            s.render.maxBounces = b;
            add("bounces=" + std::to_string(b), "bounces", true, s);
        }
        // The early stop of the bounces on its own: its test costs a little in
        // every pixel and saves whole bounces where it fires.
        if (definesFor(scene, ImplementationFacts{}, Purpose::EveryView).count("RL_BOUNCE_CUTOFF")) {
            Variant* v = add("no-early-stop", "bounces", true, scene);
            v->withoutDefines.push_back("RL_BOUNCE_CUTOFF");
        }
    }
    if (wanted(options, "spp")) {
        for (int spp : {1, 4, 9, 16}) {
            if (spp == r.spp && wanted(options, "modes")) continue;
            Scene s = scene;
            s.render.spp = spp;
            add("spp=" + std::to_string(spp), "spp", true, s);
        }
    }
    if (wanted(options, "resolution")) {
        for (int k : {2, 4}) {
            Scene s = scene;
            s.render.width = std::max(1, (r.width + k - 1) / k);
            s.render.height = std::max(1, (r.height + k - 1) / k);
            add("res=1/" + std::to_string(k), "resolution", true, s);
        }
    }
    if (wanted(options, "models")) {
        for (const ModelVariant& mv : modelVariants()) {
            Scene s = scene;
            s.model = mv.model;
            Variant* v = add(mv.name, "models", true, s);
            if (modelDefines(mv.model).empty())
                v->skipReason = "not in GLSL yet (modelDefines() gives no define for it)";
        }
    }
    if (wanted(options, "strategies")) {
        // The numerical strategies: a naive version of one exercise's
        // function, one of the mistakes its checker must catch, named by
        // its unit ("bench_strategies" in unit.json).
        for (const ExerciseInfo& e : allExercises())
            for (const BenchStrategy& st : e.benchStrategies) {
                Variant* v = add("strategy:" + st.name, "strategies", true, scene);
                const fs::path file = sourceRoot() / e.unitDir() / st.mutant;
                if (fs::is_regular_file(file))
                    v->overrides[e.file()] = file;
                else if (!hasSolutions())
                    v->skipReason = "not in this copy: a student edition has no mutants (" + e.unitDir() + "/" +
                                    st.mutant + ")";
                else
                    v->skipReason = "strategy file " + e.unitDir() + "/" + st.mutant + " not found";
            }
    }
    if (wanted(options, "environment") && scene.environment) {
        // The GL picture's approximations of environment light, one setting
        // changed at a time (bench/environment_sweep.h), then the exact
        // reference without visibility: what leaving V out costs them all.
        for (const EnvironmentApproximation& a : environmentSweep()) {
            Variant* v = add(environmentVariantName(a), "environment", true, scene);
            v->environment = a;
            v->skipReason = environmentApproximationUnsupported(a);
            v->withDefines = environmentDefines(a);  // not the course picture then: the same program plus the define
        }
        add("exact:no-V", "environment", false, scene)->exactWithoutVisibility = true;
    }
    return out;
}

// --pictures: <dir>/<scene>-<variant>.png and .pfm, the variant's ':' and
// '=' made file-name safe.
void savePicture(const fs::path& dir, const std::string& scene, const std::string& variant,
                 const Rendering& picture) {
    if (dir.empty() || picture.display.width == 0) return;
    std::string name = scene + "-" + variant;
    for (char& c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_')) c = '_';
    writePng((dir / (name + ".png")).string(), picture.display);
    if (!picture.radiance.rgb.empty()) writePfm((dir / (name + ".pfm")).string(), picture.radiance);
}

Rendering resampleNearest(const Rendering& image, int width, int height) {
    Rendering out;
    out.display = {width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    bool hasRadiance = !image.radiance.rgb.empty();
    if (hasRadiance) out.radiance = {width, height, std::vector<float>(std::size_t(width) * height * 3)};
    for (int y = 0; y < height; ++y) {
        int sy = std::min(image.display.height - 1, int((y + 0.5) * image.display.height / height));
        for (int x = 0; x < width; ++x) {
            int sx = std::min(image.display.width - 1, int((x + 0.5) * image.display.width / width));
            for (int c = 0; c < 3; ++c) {
                out.display.at(x, y)[c] = image.display.at(sx, sy)[c];
                if (hasRadiance) out.radiance.at(x, y)[c] = image.radiance.at(sx, sy)[c];
            }
        }
    }
    return out;
}

namespace {


const char* clockName(Clock clock) {
    switch (clock) {
    case Clock::Gpu: return "GL_TIME_ELAPSED queries";
    case Clock::Wall: return "the wall clock around draw + glFinish";
    case Clock::Cpu: return "the process CPU time (all threads) around draw + glFinish";
    default: return "auto";
    }
}

Measurement describe(const Variant& v) {
    Measurement m;
    m.variant = v.name;
    m.sweep = v.sweep;
    m.mode = v.textbook ? "textbook" : v.expert ? "expert" : !v.outside.empty() ? "outside" : v.exactWithoutVisibility ? "reference"
           : modeName(v.specialised, v.picture);
    m.width = v.scene.render.width;
    m.height = v.scene.render.height;
    m.spp = v.scene.render.spp;
    m.maxBounces = v.scene.render.maxBounces;
    return m;
}

// One renderer per size, so that no timed frame reallocates its targets.
// One renderer per picture size and environment approximation, so that the
// rounds of timed frames never upload an approximation's textures anew
// between two variants' frames (a frame after a fresh upload of a few
// megabytes ran up to 1.5 times slower on llvmpipe, every program alike).
struct RendererSlot {
    int width = 0, height = 0;
    EnvironmentSettings environment;
    std::unique_ptr<GlRenderer> renderer;
};
using Renderers = std::vector<RendererSlot>;
GlRenderer& rendererFor(Renderers& renderers, const Variant& v) {
    const EnvironmentSettings e = environmentSettings(v.environment.value_or(EnvironmentApproximation{}));
    const int w = v.scene.render.width, h = v.scene.render.height;
    auto slot = std::find_if(renderers.begin(), renderers.end(), [&](const RendererSlot& r) {
        return r.width == w && r.height == h && r.environment == e;
    });
    if (slot == renderers.end()) {
        renderers.push_back({w, h, e, std::make_unique<GlRenderer>()});
        return *renderers.back().renderer;
    }
    return *slot->renderer;
}

// Builds one variant's program (each call a copy of its own, compiled and
// placed in memory anew: Options::compiles).
PictureProgram buildVariant(const Variant& v, const fs::path& implDir) {
    PictureProgram program;
    if (v.textbook) {
        program.program = buildTextbook();
        setTextbookUniforms(program.program, v.scene);
        return program;
    }
    if (v.expert) {
        program.program = buildExpert(v.scene);  // the scene's numbers are compiled in
        return program;
    }
    if (!v.outside.empty()) {
        program.program = buildOutside(v.outside, v.scene);
        return program;
    }
    Implementation impl{implDir, v.overrides};
    // The mode's purpose (modeName()); "specialised" is what `raylab render` compiles.
    const Purpose purpose = v.specialised ? (v.picture ? Purpose::Picture : Purpose::EveryView)
                                          : (v.picture ? Purpose::GenericPicture : Purpose::Generic);
    const ImplementationFacts facts = implementationFacts(impl);
    ShaderDefines defines = definesFor(v.scene, facts, purpose);
    for (const std::string& name : v.withoutDefines) defines.erase(name);
    for (const auto& [name, value] : v.withDefines) defines[name] = value;
    return buildPictureProgram(impl, defines);
}

// Measures every variant of one scene. Programs are built first (a variant
// that does not build is skipped with the first line of its error), each is
// warmed up and its picture compared with the reference, then the timed
// frames run in rounds, one frame of each variant per round, so that a
// change in the machine's load during the run touches every variant alike.
std::vector<Measurement> measureScene(const std::string& sceneName, const std::vector<Variant>& variants,
                                      const Rendering& reference, const ExactReferences* exact, const Options& o,
                                      const fs::path& implDir, Clock clock, std::ostream& log) {
    std::vector<Measurement> out;
    std::vector<PictureProgram> programs(variants.size());
    Renderers renderers;
    for (std::size_t i = 0; i < variants.size(); ++i) {
        const Variant& v = variants[i];
        Measurement m = describe(v);
        m.scene = sceneName;
        m.skipped = true;
        m.note = v.skipReason;
        if (exact && (v.environment || v.exactWithoutVisibility)) {
            m.referenceSamples = exact->samples;
            m.referenceNoiseLsb = exact->noiseMeanLsb;
            m.referenceNoiseOffFraction = exact->noiseOffFraction;
        }
        if (v.exactWithoutVisibility) {
            // No GL frame: the reference without V against the one with V,
            // timed by its own wall clock (a CPU render: kept off the front).
            m.width = exact->withoutVisibility.display.width;
            m.height = exact->withoutVisibility.display.height;
            m.error = compareRenderings(exact->withoutVisibility, exact->withVisibility);
            m.errorWithoutVisibility = compareRenderings(exact->withoutVisibility, exact->withoutVisibility);
            m.msMedian = m.msMin = m.msMax = exact->msWithoutVisibility;
            m.frames = 1;
            m.clock = "cpu-reference";
            m.skipped = false;
            m.note = "the CPU reference itself, wall clock, not a GL frame";
            out.push_back(m);
            continue;
        }
        if (v.skipReason.empty()) {
            try {
                auto start = std::chrono::steady_clock::now();
                programs[i] = buildVariant(v, implDir);
                m.compileMs = msSince(start);
                GlRenderer& renderer = rendererFor(renderers, v);
                const auto tables = std::chrono::steady_clock::now();
                // An environment's tables are computed here, once per image and settings (cached after).
                renderer.setScene(v.scene, environmentSettings(v.environment.value_or(EnvironmentApproximation{})));
                gl::Finish();
                if (v.environment) m.tablesMs = msSince(tables);
                FrameSettings frame = frameFromScene(v.scene);
                const auto firstDraw = std::chrono::steady_clock::now();
                renderer.drawChecked(programs[i], frame);  // llvmpipe compiles here; marked pixels: their exact program
                gl::Finish();
                m.firstDrawMs = msSince(firstDraw);
                for (int k = 1; k < o.warmup; ++k) renderer.draw(programs[i], frame);
                gl::Finish();
                FrameSettings timedFrame = frame;
                timedFrame.radiance = false;  // the live view's frame: frames timed below store the display alone
                const std::vector<double> trials = keepFastestCopy(
                    programs[i], o.compiles, [&] { return buildVariant(v, implDir); },
                    [&](const PictureProgram& p) {
                        renderer.prepare(timedFrame);
                        return timeFrame(renderer, p, timedFrame, clock);
                    });
                if (!trials.empty()) {
                    std::ostringstream line;
                    line << "bench: " << sceneName << " " << m.variant << ": copies";
                    for (double t : trials) line << " " << std::fixed << std::setprecision(2) << t;
                    line << " ms a frame, the fastest kept\n";
                    log << line.str();
                    renderer.drawChecked(programs[i], frame);  // the picture compared below: the kept copy's, with its radiance
                    gl::Finish();
                }
                Rendering got = renderer.readBack();
                savePicture(o.picturesDir, sceneName, m.variant, got);
                const Rendering& expected = v.environment && exact ? exact->withVisibility : reference;
                const bool noReference = expected.display.width == 0;  // a student edition: none in this copy
                if (!noReference &&
                    (got.display.width != expected.display.width || got.display.height != expected.display.height))
                    got = resampleNearest(got, expected.display.width, expected.display.height);
                if (noReference) {
                    // times only: the error columns stay 0, and the note says why
                } else if (v.environment && exact) {
                    m.error = compareRenderings(got, exact->withVisibility);
                    m.errorWithoutVisibility = compareRenderings(got, exact->withoutVisibility);
                } else {
                    m.error = compareRenderings(got, reference);
                }
                m.skipped = false;
                m.clock = clock == Clock::Gpu ? "gpu" : clock == Clock::Wall ? "wall" : "cpu";
                m.note = noReference ? "no error: the CPU reference is not in this copy (a student edition)" : "";
            } catch (const Error& e) {  // ShaderError included: a variant that does not build
                if (!v.outside.empty()) throw;  // asked for by name: its error (file:line) ends the run
                programs[i] = PictureProgram();
                m.note = std::string("does not build: ") + firstLine(e.what());
            }
        }
        out.push_back(m);
    }

    std::vector<std::vector<double>> times(variants.size());
    // What each renderer holds: the scene (as its JSON text) and environment
    // settings it was last given. A variant with the same leaves it as it is,
    // so that a timed frame never pays for the scene's upload or its sky
    // tiles (computed once per camera, as in the live view, and cached by the
    // renderer until the next setScene) when the variant before it drew the
    // same scene: every variant in a round otherwise redid them in its frame.
    std::vector<std::string> sceneKeys(variants.size());
    for (std::size_t i = 0; i < variants.size(); ++i) sceneKeys[i] = sceneToJson(variants[i].scene).dump();
    std::map<const GlRenderer*, std::pair<std::string, EnvironmentSettings>> holding;
    for (int round = 0; round < o.frames; ++round) {
        for (std::size_t i = 0; i < variants.size(); ++i) {
            if (out[i].skipped || variants[i].exactWithoutVisibility) continue;
            GlRenderer& renderer = rendererFor(renderers, variants[i]);
            // (a new approximation's textures are uploaded here, before the clock starts)
            const EnvironmentSettings settings =
                environmentSettings(variants[i].environment.value_or(EnvironmentApproximation{}));
            auto held = holding.find(&renderer);
            if (held == holding.end() || held->second.first != sceneKeys[i] || !(held->second.second == settings)) {
                renderer.setScene(variants[i].scene, settings);
                holding[&renderer] = {sceneKeys[i], settings};
            }
            FrameSettings frame = frameFromScene(variants[i].scene);
            frame.radiance = false;  // as the live view draws a frame (FrameSettings::radiance)
            renderer.prepare(frame);
            // One untimed frame first: the variant before this one (the generic
            // program draws for half a second) has evicted this one's code and
            // data from the caches, and a steady stream of frames (the live
            // view, the bench's own claim of time per frame) finds them warm.
            // Measured: the metal row's picture 1.6 to 3.6 ms a frame from one
            // run to the next without it (docs/performance.md).
            renderer.draw(programs[i], frame);
            times[i].push_back(timeFrame(renderer, programs[i], frame, clock));
        }
    }
    for (std::size_t i = 0; i < variants.size(); ++i) {
        Measurement& m = out[i];
        if (!m.skipped && !variants[i].exactWithoutVisibility) {
            m.frames = int(times[i].size());
            m.msMedian = median(times[i]);
            m.msMin = *std::min_element(times[i].begin(), times[i].end());
            m.msMax = *std::max_element(times[i].begin(), times[i].end());
        }
        char line[512];
        if (m.skipped)
            std::snprintf(line, sizeof line, "bench: %s %-28s skipped: %s\n", sceneName.c_str(), m.variant.c_str(),
                          m.note.c_str());
        else
            std::snprintf(line, sizeof line, "bench: %s %-28s %8.2f ms (min %.2f, max %.2f)  mean %.3f LSB\n",
                          sceneName.c_str(), m.variant.c_str(), m.msMedian, m.msMin, m.msMax, m.error.meanLsb);
        log << line;
    }
    return out;
}

}  // namespace

std::vector<Measurement> runBench(const Options& options, std::ostream& log, std::string* contextOut) {
    if (options.width < 1 || options.height < 1) throw Error("bench: the size must be at least 1x1");
    if (options.frames < 1) throw Error("--frames: at least 1 timed frame");
    if (options.warmup < 0) throw Error("--warmup: cannot be negative");
    if (options.compiles < 1) throw Error("--compiles: at least 1 copy of each program");
    int n = int(std::lround(std::sqrt(double(options.referenceSpp))));
    if (options.referenceSpp < 1 || n * n != options.referenceSpp)
        throw Error("--reference-spp: must be a square number (1, 4, 9, 16, ...), not " +
                    std::to_string(options.referenceSpp));
    for (const std::string& s : options.sweeps)
        if (std::find(sweepNames().begin(), sweepNames().end(), s) == sweepNames().end())
            throw Error("--sweeps: unknown group " + quotedValue(s) + " (expected modes, layers, bounces, spp, resolution, models, strategies, environment)");

    std::vector<std::string> files = options.scenes;
    if (files.empty()) files.push_back((scenesDir() / "lecture.json").string());
    fs::path implDir = options.implDir.empty() ? defaultImplementationDir() : options.implDir;
    if (!fs::is_directory(implDir)) throw Error("--impl: " + implDir.string() + " is not a directory");

    // Load every scene first: a typo in the last file fails before minutes of work.
    std::vector<Scene> scenes;
    for (const std::string& file : files) {
        LoadedScene loaded = loadSceneFile(file);
        for (const auto& w : loaded.warnings) log << "raylab: warning: " << w << "\n";
        Scene s = loaded.scene;
        s.render.width = options.width;
        s.render.height = options.height;
        scenes.push_back(s);
    }

    auto context = createHeadlessContext(parseBackend(options.backend));
    Clock clock = options.clock;
    if (clock == Clock::Auto) clock = isSoftwareRasteriser(context->description()) ? Clock::Wall : Clock::Gpu;
    if (contextOut) *contextOut = context->description();
    log << "bench: " << context->description() << "\n"
        << "bench: timing with " << clockName(clock)
        << ", " << options.warmup << " warm-up and " << options.frames << " timed frames per variant"
        << (options.compiles > 1 ? ", the fastest of " + std::to_string(options.compiles) + " copies of each program"
                                 : std::string())
        << "\n";
    std::vector<Measurement> out;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Scene& scene = scenes[i];
        std::string name = sceneName(files[i]);
        const std::vector<Variant> variants = makeVariants(scene, options);
        const bool environmentRows = std::any_of(variants.begin(), variants.end(), [](const Variant& v) {
            return v.environment || v.exactWithoutVisibility;
        });
        const bool otherRows = std::any_of(variants.begin(), variants.end(), [](const Variant& v) {
            return !v.environment && !v.exactWithoutVisibility;
        });
        // The converged reference of every other sweep; the environment
        // sweep's exact references, computed once per scene and run.
        Rendering reference;
        if (!ref::referenceInThisCopy()) {
            log << "bench: " << name << ": not in this copy: a student edition has no CPU reference; "
                << "times only, no error columns\n";
        } else if (otherRows) {
            Scene converged = scene;
            converged.render.spp = options.referenceSpp;
            auto start = std::chrono::steady_clock::now();
            reference = ref::renderCpu(converged);
            log << "bench: " << name << ": CPU reference " << scene.render.width << "x" << scene.render.height
                << " at " << options.referenceSpp << " spp in " << int(msSince(start)) << " ms\n";
        }
        std::optional<ExactReferences> exact;
        if (environmentRows && ref::referenceInThisCopy()) {
            log << "bench: " << name << ": ";
            exact = exactReferences(scene, options.environmentSamples, log);
            savePicture(options.picturesDir, name, "exact", exact->withVisibility);
            savePicture(options.picturesDir, name, "exact-no-V", exact->withoutVisibility);
        }
        std::vector<Measurement> rows = measureScene(name, variants, reference, exact ? &*exact : nullptr, options,
                                                     implDir, clock, log);
        out.insert(out.end(), rows.begin(), rows.end());
    }
    markParetoFronts(out);
    return out;
}

void markParetoFronts(std::vector<Measurement>& measurements) {
    std::vector<std::string> names;
    for (const Measurement& m : measurements)
        if (std::find(names.begin(), names.end(), m.scene) == names.end()) names.push_back(m.scene);
    for (const std::string& scene : names) {
        std::vector<std::size_t> rows;
        std::vector<ParetoPoint> points;
        for (std::size_t i = 0; i < measurements.size(); ++i) {
            if (measurements[i].scene != scene || measurements[i].skipped || measurements[i].mode == "reference")
                continue;
            rows.push_back(i);
            points.push_back({measurements[i].msMedian, measurements[i].error.meanLsb});
        }
        std::vector<bool> front = paretoFront(points);
        for (std::size_t k = 0; k < rows.size(); ++k) measurements[rows[k]].onFront = front[k];
    }
}

double ModeComparison::speedup() const {
    if (!generic || !specialised || specialised->msMedian <= 0) return 0;
    return generic->msMedian / specialised->msMedian;
}

double ModeComparison::overTextbook() const {
    if (!textbook || !specialised || specialised->msMedian <= 0) return 0;
    return textbook->msMedian / specialised->msMedian;
}

bool withinYardstickBudget(const Measurement& yardstick, const Measurement& program) {
    constexpr double kMeanLsb = 0.05, kOffFraction = 0.005;  // see bench.h
    return yardstick.error.meanLsb <= program.error.meanLsb + kMeanLsb &&
           yardstick.error.offFraction <= program.error.offFraction + kOffFraction;
}

const Measurement* ModeComparison::strongest() const {
    const Measurement* best = nullptr;
    std::vector<const Measurement*> candidates{expert, textbook};  // the expert first: it wins a tie
    for (const Measurement* m : outside)  // the team's own are held to the budget by the tests
        if (!specialised || withinYardstickBudget(*m, *specialised)) candidates.push_back(m);
    for (const Measurement* m : candidates)
        if (m && (!best || m->msMedian < best->msMedian)) best = m;
    return best;
}

double ModeComparison::overStrongest() const {
    const Measurement* y = strongest();
    if (!y || !specialised || specialised->msMedian <= 0) return 0;
    return y->msMedian / specialised->msMedian;
}

std::vector<ModeComparison> modeComparisons(const std::vector<Measurement>& measurements) {
    std::vector<ModeComparison> out;
    for (const Measurement& m : measurements) {
        if (m.sweep != "modes" || m.skipped) continue;
        auto it = std::find_if(out.begin(), out.end(), [&](const ModeComparison& c) { return c.scene == m.scene; });
        if (it == out.end()) {
            out.push_back({m.scene, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, {}});
            it = out.end() - 1;
        }
        if (m.mode == "generic") it->generic = &m;
        else if (m.mode == "specialised") it->specialised = &m;
        else if (m.mode == "generic-picture") it->genericPicture = &m;
        else if (m.mode == "specialised-full") it->specialisedFull = &m;
        else if (m.mode == "textbook") it->textbook = &m;
        else if (m.mode == "expert") it->expert = &m;
        else if (m.mode == "outside") it->outside.push_back(&m);
    }
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const ModeComparison& c) { return !c.generic || !c.specialised; }),
              out.end());
    return out;
}

namespace {
std::string fixed(double v, int digits) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}
std::string general(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}
}  // namespace

std::string formatTable(const std::vector<Measurement>& measurements) {
    std::ostringstream s;
    char line[512];
    std::snprintf(line, sizeof line, "%-10s %-28s %9s %4s %3s %9s %9s %7s %6s %7s %9s %7s %5s\n", "scene", "variant",
                  "size", "spp", "bnc", "ms median", "ms min", "mean", "p99", "off %", "relMSE", "PSNR", "front");
    s << line;
    for (const Measurement& m : measurements) {
        std::string size = std::to_string(m.width) + "x" + std::to_string(m.height);
        if (m.skipped) {
            std::snprintf(line, sizeof line, "%-10s %-28s %9s %4d %3d   skipped: %s\n", m.scene.c_str(),
                          m.variant.c_str(), size.c_str(), m.spp, m.maxBounces, m.note.c_str());
        } else {
            std::snprintf(line, sizeof line, "%-10s %-28s %9s %4d %3d %9.2f %9.2f %7.3f %6.1f %7.3f %9.2e %7s %5s\n",
                          m.scene.c_str(), m.variant.c_str(), size.c_str(), m.spp, m.maxBounces, m.msMedian, m.msMin,
                          m.error.meanLsb, m.error.p99Lsb, 100 * m.error.offFraction, m.error.relMse,
                          fixed(m.error.psnr, 2).c_str(), m.onFront ? "*" : "");
        }
        s << line;
    }
    std::string clock = "gpu";
    for (const Measurement& m : measurements)
        if (!m.skipped) clock = m.clock;
    s << "(ms: median time per frame, "
      << (clock == "gpu" ? "GL_TIME_ELAPSED" : clock == "wall" ? "wall clock around draw + glFinish"
                                                                 : "process CPU time around draw + glFinish")
      << "; mean, p99: difference from the converged CPU\n reference in 8-bit steps; off %: pixels off by more "
         "than 1/255; front *: on the Pareto front of time and mean error)\n";
    return s.str();
}

std::string formatComparisons(const std::vector<Measurement>& measurements) {
    // Every ratio is a speed ratio against the strongest yardstick measured in
    // the same run (yardstick ms / program ms: above 1 is faster than it).
    std::ostringstream s;
    const std::vector<ModeComparison> comparisons = modeComparisons(measurements);
    if (comparisons.empty()) return "";
    for (const ModeComparison& c : comparisons) {
        char line[768];
        const Measurement* y = c.strongest();
        auto error = [](const Measurement& m) {
            char text[128];
            std::snprintf(text, sizeof text, "mean %.3f LSB, p99 %.1f, off %.3f%%", m.error.meanLsb, m.error.p99Lsb,
                          100 * m.error.offFraction);
            return std::string(text);
        };
        if (!y) {
            std::snprintf(line, sizeof line, "%s at %dx%d: specialised %.2f ms, generic %.2f ms per frame (no yardstick ran)\n",
                          c.scene.c_str(), c.specialised->width, c.specialised->height, c.specialised->msMedian,
                          c.generic->msMedian);
            s << line;
            continue;
        }
        auto ratio = [&](const Measurement* m) { return m && m->msMedian > 0 ? y->msMedian / m->msMedian : 0.0; };
        std::snprintf(line, sizeof line,
                      "%s at %dx%d: against the strongest yardstick (%s, %.2f ms, %s):\n"
                      "  specialised %.2fx (%.2f ms, %s)\n",
                      c.scene.c_str(), c.specialised->width, c.specialised->height, y->variant.c_str(), y->msMedian,
                      error(*y).c_str(), ratio(c.specialised), c.specialised->msMedian,
                      error(*c.specialised).c_str());
        s << line;
        std::snprintf(line, sizeof line, "  generic %.2fx (%.2f ms, %s)\n", ratio(c.generic), c.generic->msMedian,
                      error(*c.generic).c_str());
        s << line;
        if (c.genericPicture && c.specialisedFull) {
            std::snprintf(line, sizeof line,
                          "  generic-picture %.2fx (%.2f ms), specialised-full %.2fx (%.2f ms)\n", ratio(c.genericPicture),
                          c.genericPicture->msMedian, ratio(c.specialisedFull), c.specialisedFull->msMedian);
            s << line;
        }
        std::vector<const Measurement*> others{c.expert, c.textbook};
        others.insert(others.end(), c.outside.begin(), c.outside.end());
        for (const Measurement* other : others) {
            if (!other || other == y) continue;
            const bool counts = other->mode != "outside" || withinYardstickBudget(*other, *c.specialised);
            std::snprintf(line, sizeof line, "  %s (%s) %.2fx (%.2f ms, %s)\n", other->variant.c_str(),
                          other->mode == "expert"    ? "the expert yardstick"
                          : !counts                  ? "from outside, not counted: its picture is off by more than the budget"
                          : other->mode == "outside" ? "a yardstick from outside"
                                                     : "the straightforward yardstick",
                          ratio(other), other->msMedian, error(*other).c_str());
            s << line;
        }
        if (!c.expert)
            s << "  (the expert yardstick did not run on this scene: the ratios are against " << y->variant << ")\n";
        double more = c.specialised->error.meanLsb - c.generic->error.meanLsb;
        if (more == 0 && c.generic->error.maxLsb == c.specialised->error.maxLsb) {
            s << "  the same error against the reference for specialised and generic\n";
        } else {
            std::snprintf(line, sizeof line, "  error against the reference, specialised minus generic: mean %+.4f LSB\n",
                          more);
            s << line;
        }
    }
    s << "(ratios: the strongest yardstick's ms / the row's ms, measured in this run: above 1 is faster than it)\n";
    return s.str();
}

std::string toCsv(const std::vector<Measurement>& measurements) {
    std::ostringstream s;
    s << "scene,variant,sweep,mode,width,height,spp,max_bounces,frames,ms_median,ms_min,ms_max,clock,compile_ms,"
         "first_draw_ms,err_mean_lsb,err_p99_lsb,err_max_lsb,off_frac,relmse,psnr,non_finite,pareto,skipped,note,"
         "err_mean_lsb_no_v,off_frac_no_v,reference_samples,reference_noise_lsb,reference_noise_off_frac,tables_ms\n";
    for (const Measurement& m : measurements) {
        std::string note = m.note;
        std::replace(note.begin(), note.end(), '"', '\'');
        s << m.scene << "," << m.variant << "," << m.sweep << "," << m.mode << "," << m.width << "," << m.height << ","
          << m.spp << "," << m.maxBounces << "," << m.frames << ",";
        if (m.skipped) {
            s << ",,,,,,,,,,,,,0,1,\"" << note << "\",,,,,,\n";
            continue;
        }
        s << fixed(m.msMedian, 3) << "," << fixed(m.msMin, 3) << "," << fixed(m.msMax, 3) << "," << m.clock << ","
          << fixed(m.compileMs, 1) << "," << fixed(m.firstDrawMs, 1) << "," << general(m.error.meanLsb) << "," << general(m.error.p99Lsb) << ","
          << m.error.maxLsb << "," << general(m.error.offFraction) << "," << general(m.error.relMse) << ","
          << general(m.error.psnr) << "," << m.error.nonFinite << "," << (m.onFront ? 1 : 0) << ",0,\"" << note
          << "\",";
        if (m.referenceSamples > 0)
            s << general(m.errorWithoutVisibility.meanLsb) << "," << general(m.errorWithoutVisibility.offFraction) << ","
              << m.referenceSamples << "," << general(m.referenceNoiseLsb) << ","
              << general(m.referenceNoiseOffFraction) << "," << fixed(m.tablesMs, 1) << "\n";
        else
            s << ",,,,,\n";
    }
    return s.str();
}

void writeTextFile(const fs::path& path, const std::string& text) {
    writeFileAtomic(path, text);
}

std::string loadAverage() {
    std::error_code ec;
    if (!fs::is_regular_file("/proc/loadavg", ec)) return "";
    try {
        std::istringstream in(readRegularFile("/proc/loadavg", 4096));
        std::string a, b, c;
        in >> a >> b >> c;
        return a + " " + b + " " + c;
    } catch (const Error&) {
        return "";
    }
}

std::string markdownSectionName(const std::set<std::string>& sweeps) {
    return sweeps.size() == 1 && sweeps.count("environment") ? "bench-environment" : "bench";
}

namespace {
std::string beginMarker(const std::string& section) { return "<!-- " + section + ":begin -->"; }
std::string endMarker(const std::string& section) { return "<!-- " + section + ":end -->"; }

// Where the section lies: each marker alone on its line (a document may
// quote the markers in its text), the begin before the end. {npos, npos}
// when there is none.
std::pair<std::size_t, std::size_t> markedSection(const std::string& text, const std::string& section) {
    auto onItsOwnLine = [&](const std::string& marker, std::size_t from) {
        for (std::size_t at = text.find(marker, from); at != std::string::npos; at = text.find(marker, at + 1)) {
            bool starts = at == 0 || text[at - 1] == '\n';
            std::size_t after = at + marker.size();
            bool ends = after == text.size() || text[after] == '\n' || text[after] == '\r';
            if (starts && ends) return at;
        }
        return std::string::npos;
    };
    std::size_t begin = onItsOwnLine(beginMarker(section), 0);
    if (begin == std::string::npos) return {std::string::npos, std::string::npos};
    std::size_t end = onItsOwnLine(endMarker(section), begin);
    if (end == std::string::npos) return {std::string::npos, std::string::npos};
    return {begin, end};
}
}  // namespace

std::string markdownSection(const MarkdownRun& run, const std::vector<Measurement>& measurements,
                            const fs::path& markdownFile) {
    std::ostringstream s;
    s << beginMarker(run.section) << "\n<!-- written by `raylab bench --markdown`: run the command below again, do not edit -->\n\n";
    s << "```sh\n" << run.command << "\n```\n\n";
    s << "Context: " << run.context;
    if (!run.load.empty()) s << "; load average before the run " << run.load << " (1, 5, 15 minutes)";
    s << ".\n\n";
    if (!run.plot.empty()) {
        fs::path base = fs::absolute(markdownFile).lexically_normal().parent_path();
        std::string link = fs::absolute(run.plot).lexically_normal().lexically_relative(base).generic_string();
        s << "![Error against time per frame](" << link << ")\n\n";
    }
    const std::string environment = formatEnvironmentTable(measurements);
    if (run.section == "bench-environment")  // the environment sweep alone: its own table says it all
        s << "```text\n" << environment << "```\n" << endMarker(run.section);
    else
        s << "```text\n" << formatTable(measurements) << "\n" << formatComparisons(measurements)
          << (environment.empty() ? "" : "\n" + environment) << "```\n" << endMarker(run.section);
    return s.str();
}

void checkMarkdownTarget(const fs::path& file, const std::string& section) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(file, ec))) return;  // a new file
    std::string text = readRegularFile(file, 16 << 20, "Markdown file");
    if (markedSection(text, section).first == std::string::npos)
        throw Error("--markdown: " + file.string() + " exists and has no " + beginMarker(section) + " ... " +
                    endMarker(section) + " section (each marker on a line of its own) to replace (not changed)");
}

void writeMarkdown(const fs::path& file, const MarkdownRun& run, const std::vector<Measurement>& measurements) {
    checkMarkdownTarget(file, run.section);
    std::string section = markdownSection(run, measurements, file);
    std::error_code ec;
    if (fs::is_regular_file(file, ec)) {
        std::string text = readRegularFile(file, 16 << 20, "Markdown file");
        auto [begin, end] = markedSection(text, run.section);
        if (begin != std::string::npos) {
            writeFileAtomic(file, text.substr(0, begin) + section + text.substr(end + endMarker(run.section).size()));
            return;
        }
    }
    writeFileAtomic(file, section + "\n");
}

}  // namespace rl::bench
