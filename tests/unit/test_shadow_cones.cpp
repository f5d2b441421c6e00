// render/shadow_cones.h: the cones from each light within which a sphere can
// block a shadow ray. A program for one picture asks the exact segment test
// only about the spheres whose cone passes, so a cone must never turn away a
// sphere that the shader's own float32 segment test would find in the way:
// the picture would lose a shadow. Checked here against that test, computed
// in float32 as the shader computes it, on rays that graze the spheres.
#include "core/float_range.h"
#include "render/shadow_cones.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace rl {
namespace {

// shaders/intersect_scene.glsl, segmentCrossesSphere(), in float32.
bool segmentCrossesSphere(glm::vec3 o, glm::vec3 d, float tMax, glm::vec3 c, float r) {
    glm::vec3 f = c - o;
    float b = glm::dot(f, d);
    float s = std::clamp(b, 0.0f, tMax);
    glm::vec3 nearest = f - s * d, end = f - tMax * d;
    float rr = r * r;
    return glm::dot(nearest, nearest) <= rr && (glm::dot(f, f) > rr || glm::dot(end, end) > rr);
}

// shaders/intersect_scene.glsl, mayShadow() with RL_SHADOW_CONES, in float32.
bool conePasses(const ShadowCone& cone, glm::vec3 dir, float tMax) {
    return -glm::dot(dir, cone.axis) >= cone.minCos && tMax >= cone.nearest;
}

// A random unit vector at angle `angle` from the unit vector `axis`.
glm::dvec3 atAngle(glm::dvec3 axis, double angle, std::mt19937& rng) {
    std::normal_distribution<double> g;
    glm::dvec3 side;
    do side = glm::dvec3(g(rng), g(rng), g(rng)) - axis * glm::dot(axis, side); while (glm::length(side) < 1e-3);
    side = glm::normalize(side - axis * glm::dot(axis, side));
    return std::cos(angle) * axis + std::sin(angle) * side;
}

Scene randomScene(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
    Scene s;
    int spheres = 1 + int(unit(rng) * 8);
    for (int i = 0; i < spheres; ++i) {
        Sphere sp;
        sp.center = glm::dvec3(u(rng), u(rng), u(rng)) * 5.0;
        sp.radius = std::exp(std::log(0.01) + unit(rng) * std::log(300.0));
        s.spheres.push_back(sp);
    }
    if (unit(rng) < 0.5) {  // a ground: the cones' widest case
        Sphere ground;
        ground.radius = unit(rng) < 0.5 ? 1000.0 : 1e5;
        ground.center = glm::dvec3(0.0, -ground.radius - 1.0, 0.0);
        s.spheres.push_back(ground);
    }
    int lights = 1 + int(unit(rng) * 3);
    for (int k = 0; k < lights; ++k) {
        Light l;
        // Sometimes at or inside a sphere: those cones must pass everything.
        const Sphere& near = s.spheres[std::size_t(unit(rng) * spheres)];
        l.position = unit(rng) < 0.2 ? near.center + glm::dvec3(near.radius * (0.5 + unit(rng)), 0.0, 0.0)
                                     : glm::dvec3(u(rng), u(rng), u(rng)) * 8.0;
        s.lights.push_back(l);
    }
    s.camera.position = glm::dvec3(0.0, 2.0, 12.0);
    return s;
}

TEST(ShadowCones, NoConeTurnsAwayASphereTheSegmentTestFinds) {
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    long blocked = 0, grazing = 0, passedInVain = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Scene scene = randomScene(rng);
        std::vector<ShadowCone> cones = shadowCones(scene);
        ASSERT_EQ(cones.size(), scene.spheres.size() * scene.lights.size());
        const glm::dvec3 anchor = sceneAnchor(scene);
        const double unitLength = shaderUnits(scene, scene.camera.position).unit;
        auto shaderValue = [&](glm::dvec3 p) { return glm::vec3((p - anchor) / unitLength); };
        for (std::size_t k = 0; k < scene.lights.size(); ++k)
            for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
                const ShadowCone& cone = cones[k * scene.spheres.size() + j];
                const glm::vec3 light = shaderValue(scene.lights[k].position), centre = shaderValue(scene.spheres[j].center);
                const float radius = float(scene.spheres[j].radius / unitLength);
                const glm::dvec3 toCentre = glm::dvec3(centre) - glm::dvec3(light);
                const double d = glm::length(toCentre);
                for (int n = 0; n < 200; ++n) {
                    // The origin of a shadow ray towards the light: beyond the
                    // sphere along a direction that grazes its silhouette
                    // (within 1e-6 of the half-angle either way), or anywhere.
                    glm::dvec3 from;
                    if (d > radius && n % 4 != 3) {
                        double half = std::asin(std::min(1.0, radius / d)) * (1.0 + (unit(rng) - 0.5) * 2e-6);
                        double length = (d - radius) * (1.0 - 1e-6) + unit(rng) * 3.0 * (radius + d);
                        from = glm::dvec3(light) + atAngle(toCentre / d, n % 4 == 2 ? 0.0 : half, rng) * length;
                        ++grazing;
                    } else {
                        from = glm::dvec3(centre) + atAngle(glm::dvec3(0, 1, 0), unit(rng) * 3.14159, rng) *
                                                        (radius * (0.5 + unit(rng)));
                    }
                    const glm::vec3 origin(from);
                    const glm::vec3 toLight = light - origin;
                    const float distance = glm::length(toLight);
                    if (!(distance > 0.0f)) continue;
                    const glm::vec3 dir = toLight / distance;
                    const bool pass = conePasses(cone, dir, distance);
                    if (segmentCrossesSphere(origin, dir, distance, centre, radius)) {
                        ++blocked;
                        ASSERT_TRUE(pass) << "trial " << trial << ", light " << k << ", sphere " << j << " (r " << radius
                                          << ", d " << d << "): the segment test finds it, the cone turns it away";
                    } else if (pass) {
                        ++passedInVain;
                    }
                }
            }
    }
    // The test can fail only if it meets blocked rays, many of them at the edge.
    EXPECT_GT(blocked, 20000);
    EXPECT_GT(grazing, 50000);
    // And the cones do cull: most rays that cross no sphere are turned away.
    EXPECT_GT(passedInVain, 0);
    std::printf("[ measured ] %ld blocked rays all passed; %ld unblocked rays passed in vain\n", blocked, passedInVain);
}

TEST(ShadowCones, ALightInsideOrAtASphereMakesItACandidateAlways) {
    Scene s;
    Sphere a;
    a.center = {0, 0, 0};
    a.radius = 1.0;
    s.spheres = {a};
    Light inside, atSurface, outside;
    inside.position = {0.2, 0.1, 0.0};
    atSurface.position = {1.0, 0.0, 0.0};
    outside.position = {0.0, 3.0, 0.0};
    s.lights = {inside, atSurface, outside};
    std::vector<ShadowCone> cones = shadowCones(s);
    ASSERT_EQ(cones.size(), 3u);
    for (int k : {0, 1}) {
        EXPECT_LE(cones[k].minCos, -1.0f) << k;
        EXPECT_EQ(cones[k].nearest, 0.0f) << k;
    }
    // Seen from (0, 3, 0): the axis points down, half-angle asin(1/3), nearest point 2 away.
    EXPECT_NEAR(cones[2].axis.y, -1.0f, 1e-6f);
    EXPECT_NEAR(cones[2].minCos, std::sqrt(8.0 / 9.0), 1e-4);
    EXPECT_LT(cones[2].minCos, std::sqrt(8.0f / 9.0f));
    EXPECT_NEAR(cones[2].nearest, 2.0f, 1e-3f);
    EXPECT_LT(cones[2].nearest, 2.0f);
}

}  // namespace
}  // namespace rl
