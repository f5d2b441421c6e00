// The live view's generated picture program (app/render/live_course_program.h,
// issue #25): the course generator's structure with every value a uniform.
// Its source must not change with a value (a slider, a light or sphere moved
// a little, the camera orbiting), only with the structure; one program built
// for a scene must draw the picture `raylab render` draws (the course
// program) for that scene and, with its uniforms set again and nothing
// compiled, for the scene after value edits. No timing is asserted:
// `raylab bench --sweeps view` measures speed.
#include "core/paths.h"
#include "core/scene_io.h"
#include "render/course_program.h"
#include "render/gl_renderer.h"
#include "render/implementation_facts.h"
#include "render/live_course_program.h"
#include "bench/bench_test_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <vector>

using namespace rl;
namespace fs = std::filesystem;

namespace {

// Values only: materials, light colours and intensities, exposure, ambient,
// background, gamma, a light and a sphere moved a little, the camera orbited.
Scene valueEdits(Scene s) {
    for (Sphere& sphere : s.spheres) {
        sphere.material.metallic = 1.0 - sphere.material.metallic;
        sphere.material.roughness = 0.5 * sphere.material.roughness + 0.1;
        sphere.material.albedo = glm::dvec3(0.9, 0.4, 0.2) * sphere.material.albedo + 0.05;
    }
    for (Light& light : s.lights) {
        light.intensity *= 1.3;
        light.color.y *= 0.8;
    }
    if (!s.lights.empty()) s.lights[0].position.x += 0.5;
    if (s.spheres.size() > 1) s.spheres[1].center.y += 0.01;
    s.render.exposure = 1.7;
    s.render.ambient += 0.02;
    s.render.background = glm::dvec3(0.3, 0.1, 0.05);
    s.render.gamma = 2.0;
    const glm::dvec3 arm = s.camera.position - s.camera.target;  // orbit 10 degrees about the up axis
    const double c = std::cos(0.17), sn = std::sin(0.17);
    s.camera.position = s.camera.target + glm::dvec3(c * arm.x + sn * arm.z, arm.y, -sn * arm.x + c * arm.z);
    return s;
}

}  // namespace

TEST(LiveCourseProgram, ValuesNeverChangeTheSourceTheStructureDoes) {
    const Scene lecture = test::tinyScene(scenesDir() / "lecture.json");
    const std::string source = liveCourseSource(lecture, frameFromScene(lecture));
    const Scene edited = valueEdits(lecture);
    EXPECT_EQ(liveCourseSource(edited, frameFromScene(edited)), source);
    Scene bigger = edited;  // a window resized: the camera's uniforms only
    bigger.render.width = 1920;
    bigger.render.height = 1080;
    EXPECT_EQ(liveCourseSource(bigger, frameFromScene(bigger)), source);

    Scene more = lecture;
    more.spheres.push_back(more.spheres[1]);
    more.spheres.back().center.x += 7.0;
    EXPECT_NE(liveCourseSource(more, frameFromScene(more)), source) << "another sphere";
    Scene bounces = lecture;
    bounces.render.maxBounces += 1;
    EXPECT_NE(liveCourseSource(bounces, frameFromScene(bounces)), source) << "another bounce limit";
    Scene inside = lecture;  // the camera inside a sphere: another root for its camera rays
    inside.camera.position = inside.spheres[1].center;
    inside.camera.target = inside.spheres[1].center + glm::dvec3(0, 0, 1);
    EXPECT_NE(liveCourseSource(inside, frameFromScene(inside)), source) << "the camera inside a sphere";
}

TEST(LiveCourseProgram, AppliesToTheCourseFilesOnly) {
    const Scene scene = test::tinyScene(scenesDir() / "lecture.json");
    EXPECT_TRUE(liveCourseApplies(scene, implementationFacts(Implementation{solutionsDir(), {}})));
    EXPECT_FALSE(liveCourseApplies(scene, ImplementationFacts{})) << "files not known to be the course's";
}

TEST(LiveCourseProgram, DrawsTheRenderPictureAndAfterValueEditsWithoutACompile) {
    test::ensureHeadlessContext();
    const ImplementationFacts course = implementationFacts(Implementation{solutionsDir(), {}});
    int drawn = 0;
    for (const char* name : {"lecture.json", "metal-row-reflections.json", "dielectric-row.json"}) {
        const fs::path file = scenesDir() / name;
        if (!fs::exists(file)) continue;
        const Scene s = test::tinyScene(file);
        if (!liveCourseApplies(s, course)) continue;
        const std::string source = liveCourseSource(s, frameFromScene(s));
        const PictureProgram live = buildLiveCoursePicture(s, source);
        setLiveCourseValues(live.program, s, frameFromScene(s));
        test::expectWithinBudget(renderOnce(live, s, frameFromScene(s)), renderOnce(buildCoursePicture(s), s, frameFromScene(s)),
                           std::string(name) + ": live program vs render's course program");

        // The same program, its uniforms set for the edited scene.
        const Scene edited = valueEdits(s);
        ASSERT_EQ(liveCourseSource(edited, frameFromScene(edited)), source) << name << ": values only";
        setLiveCourseValues(live.program, edited, frameFromScene(edited));
        const Rendering after = renderOnce(live, edited, frameFromScene(edited));
        test::expectWithinBudget(after, renderOnce(buildCoursePicture(edited), edited, frameFromScene(edited)),
                           std::string(name) + ": after value edits, vs the course program built for them");
        ++drawn;
    }
    EXPECT_EQ(drawn, 3);
}
