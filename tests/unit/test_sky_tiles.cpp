// render/sky_tiles.h: the screen tiles where no camera ray can hit a sphere,
// which `raylab render` draws with a program that has no sphere. The tiles
// must be conservative (a pixel whose ray hits something is never sky: the
// picture would lose it) and must cover the frame exactly once.
#include "core/paths.h"
#include "core/scene_io.h"
#include "reference/cpu_reference.h"
#include "render/sky_tiles.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace rl {
namespace {

Scene load(const std::string& relative) { return loadSceneFile((sourceRoot() / relative).string()).scene; }

// Exercise 01's camera ray through pixel position (px, py), y from the bottom, in double.
glm::dvec3 rayThrough(const FrameSettings& f, double px, double py) {
    double t = std::tan(0.5 * f.fovYRadians), aspect = double(f.width) / f.height;
    double x = (2.0 * px / f.width - 1.0) * t * aspect, y = (2.0 * py / f.height - 1.0) * t;
    glm::dvec3 r(f.cameraToWorld[0]), u(f.cameraToWorld[1]), back(f.cameraToWorld[2]);
    return glm::normalize(x * r + y * u - back);
}

// Every sample position of every pixel of the sky rectangles (its corners
// and centre) misses every sphere in double; each pixel lies in exactly one
// rectangle.
void expectConservativeCover(const Scene& scene, const FrameSettings& frame) {
    SkyTiles tiles = skyTiles(scene, frame);
    std::vector<int> covered(std::size_t(frame.width) * frame.height, 0);
    glm::dvec3 eye(frame.cameraToWorld[3]);
    for (const auto* rects : {&tiles.sky, &tiles.scene})
        for (const PixelRect& r : *rects)
            for (int y = r.y; y < r.y + r.height; ++y)
                for (int x = r.x; x < r.x + r.width; ++x) {
                    ++covered[std::size_t(y) * frame.width + x];
                    if (rects != &tiles.sky) continue;
                    for (auto [dx, dy] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {0.5, 0.5}}) {
                        ref::Hit hit;
                        ASSERT_FALSE(ref::closestHit(scene, eye, rayThrough(frame, x + dx, y + dy), hit))
                            << "pixel (" << x << ", " << y << ") is sky but its ray hits sphere " << hit.sphere;
                    }
                }
    for (int c : covered) ASSERT_EQ(c, 1);
}

TEST(SkyTiles, TheCourseScenesSkyIsFoundAndNeverHidesASphere) {
    for (const char* file : {"scenes/lecture.json", "tests/bench/course-row-ground.json", "tests/bench/random-30.json"}) {
        Scene scene = load(file);
        FrameSettings frame = frameFromScene(scene);
        frame.width = 160, frame.height = 120;
        SCOPED_TRACE(file);
        expectConservativeCover(scene, frame);
        // Above the horizon is sky: a third of the picture or more.
        EXPECT_GT(skyTiles(scene, frame).skyShare, 0.3);
    }
}

TEST(SkyTiles, RandomCamerasAndSpheresNeverHideASphere) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 40; ++k) {
        Scene scene = load("scenes/lecture.json");
        scene.spheres.resize(1 + k % 5);
        for (Sphere& s : scene.spheres) {
            s.center = glm::dvec3(3 * u(rng), 3 * u(rng), -4 + 3 * u(rng));
            s.radius = 0.05 + 0.6 * (1 + u(rng));
        }
        scene.camera.position = glm::dvec3(4 * u(rng), 4 * u(rng), 4 + 2 * u(rng));
        scene.camera.fovYDegrees = 10 + 80 * (1 + u(rng)) / 2 + (k == 7 ? 89.9 : 0.0);
        FrameSettings frame = frameFromScene(scene);
        frame.width = 37 + k, frame.height = 29;  // sizes that are no multiple of a tile
        SCOPED_TRACE("case " + std::to_string(k));
        expectConservativeCover(scene, frame);
    }
}

TEST(SkyTiles, ACameraInsideASphereHasNoSky) {
    Scene scene = load("scenes/hard/camera-inside.json");
    FrameSettings frame = frameFromScene(scene);
    EXPECT_TRUE(skyTiles(scene, frame).sky.empty());
}

}  // namespace
}  // namespace rl
