// The course's generated picture program (app/render/course_program.h): what
// `raylab render` draws when every exercise file is the course's own. It must
// render the same picture as the generic program (within the core's budget
// against the CPU reference and against each other), on the bundled scenes
// and the bench's, and never replace a student's own file. No timing is
// asserted: `raylab bench` measures speed.
#include "core/file_io.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "reference/cpu_reference.h"
#include "render/course_program.h"
#include "render/define_table.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "shader/shader_library.h"
#include "bench/bench_test_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace rl;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> scenes() {
    std::vector<fs::path> out;
    for (const fs::path& dir : {scenesDir(), scenesDir() / "presets", scenesDir() / "hard", sourceRoot() / "tests" / "bench"})
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
                out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(CourseProgram, AppliesToTheCourseFilesOnlyAndNeverToAStudentsFile) {
    const Scene scene = test::tinyScene(scenesDir() / "lecture.json");
    EXPECT_TRUE(courseProgramApplies(scene, implementationFacts(Implementation{solutionsDir(), {}})));

    // One exercise file of the student's own (the course's text plus a
    // statement): that file's code must run, so the generic path is used.
    const fs::path dir = test::freshTempDir("course-program-student");
    const std::string file = "02-intersect.glsl";
    const fs::path own = dir / file;
    {
        std::ofstream out(own);
        out << readRegularFile(solutionsDir() / file, 1 << 20) << "\n// mine\nconst float MY_OWN = 1.0;\n";
    }
    Implementation student{solutionsDir(), {{file, own}}};
    const ImplementationFacts facts = implementationFacts(student);
    EXPECT_FALSE(facts.courseFile(file));
    EXPECT_FALSE(courseProgramApplies(scene, facts));
}

TEST(CourseProgram, RendersThePictureOfTheGenericProgramOnEveryBundledScene) {
    test::ensureHeadlessContext();
    int rendered = 0;
    for (const fs::path& file : scenes()) {
        const Scene s = test::tinyScene(file);
        if (!courseProgramApplies(s, implementationFacts(Implementation{solutionsDir(), {}}))) continue;  // model variants
        // Environment light is approximated in GL (docs/model.md): its error
        // has its own budget, held by EnvironmentBudget (tests/bench/test_environment_sweep.cpp).
        if (s.environment) continue;
        const std::string name = file.filename().string();
        const Rendering reference = ref::renderCpu(s);
        const Rendering generic = renderOnce(
            buildRayTracer(Implementation{solutionsDir(), {}}, definesFor(s, ImplementationFacts{}, Purpose::Generic)), s,
            frameFromScene(s));
        const Rendering course = renderOnce(buildCoursePicture(s), s, frameFromScene(s));
        test::expectWithinBudget(course, reference, name + ": course program vs CPU reference");
        test::expectWithinBudget(course, generic, name + ": course program vs generic program");
        ++rendered;
    }
    EXPECT_GE(rendered, 5);
}

// Per-tile programs (CourseProgramOptions::tilePrograms, the cost model off so
// that every group of tiles gets its own program even at 64x48, 16-pixel
// tiles) and the one-program list form (tileLists): each group's first hit
// tests only the spheres its tiles' camera rays may hit and the spheres that
// may shadow the hits' visible patches. Both only leave out tests that fail
// by geometry, so the picture is the one-program picture: the mean difference
// is held to 0.01/255 (float32 order of operations is the same; only the
// structure of the code differs) besides the core's budget. Seen failing
// (lecture: 3.4% of pixels off, mean 0.82/255) with the tiles' occluders
// left empty.
TEST(CourseProgram, PerTileProgramsRenderTheSamePicture) {
    test::ensureHeadlessContext();
    for (const fs::path& file : {scenesDir() / "lecture.json", sourceRoot() / "tests" / "bench" / "random-30.json"}) {
        const Scene s = test::tinyScene(file);
        const std::string name = file.filename().string();
        const Rendering whole = renderOnce(buildCoursePicture(s), s, frameFromScene(s));
        const Rendering reference = ref::renderCpu(s);
        for (bool lists : {false, true}) {
            if (!lists && name == "random-30.json") continue;  // a dozen programs of 30 spheres: seconds to compile each
            CourseProgramOptions options;
            options.tilePrograms = !lists;
            options.tileLists = lists;
            options.tileCostModel = false;
            options.frames = 1000;
            options.tileSize = 16;
            const PictureProgram tiled = buildCoursePicture(s, options);
            EXPECT_GE(tiled.tiles.size(), 2u) << name;  // more than the sky's group: the tiles are in use
            const Rendering got = renderOnce(tiled, s, frameFromScene(s));
            const std::string what = name + (lists ? " (tile lists)" : " (tile programs)");
            test::expectWithinBudget(got, reference, what + " vs CPU reference");
            ImageDiff d = compareRenderings(got, whole);
            SCOPED_TRACE(what + " vs the one program: " + test::describe(d));
            EXPECT_LT(d.meanLsb, 0.01);
            EXPECT_EQ(d.nonFinite, 0);
        }
    }
}
