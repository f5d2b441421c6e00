#include "checks/probe_cases.h"

#include "course/exercise_registry.h"

namespace rl {

using glm::dvec3;

// The probe scene: two spheres on a big ground, one light above, one beside.
Scene probeScene() {
    Scene s;
    auto sphere = [](dvec3 c, double r, dvec3 albedo, double rough, double metal) {
        Sphere sp;
        sp.center = c;
        sp.radius = r;
        sp.material.albedo = albedo;
        sp.material.roughness = rough;
        sp.material.metallic = metal;
        return sp;
    };
    s.spheres = {sphere({0, -100, 0}, 100, {0.6, 0.6, 0.6}, 0.8, 0),
                 sphere({0, 1, 0}, 1, {0.9, 0.2, 0.1}, 0.4, 0),
                 sphere({2.5, 0.7, 0.5}, 0.7, {0.95, 0.9, 0.6}, 0.2, 1),
                 sphere({-2.2, 0.8, -0.6}, 0.8, {0.2, 0.5, 0.9}, 0.05, 0.5),
                 // Two facing mirrors off to the side: a ray between them
                 // bounces until max_bounces ends it.
                 sphere({9, 3, 0}, 1, {0.95, 0.95, 0.95}, 0.05, 1),
                 sphere({13, 3, 0}, 1, {0.9, 0.8, 0.5}, 0.05, 1),
                 // A receiver and an occluder scaled by 1e-3, in the air far
                 // from the rest: a light next to the occluder (exercise 04).
                 sphere({-6, 4, -4}, 5e-4, {0.8, 0.8, 0.8}, 0.5, 0),
                 sphere({-6, 4.0025, -4}, 5e-4, {0.8, 0.8, 0.8}, 0.5, 0)};
    Light key;
    key.position = {1, 6, 2};
    key.intensity = 60;
    Light fill;
    fill.position = {-5, 2, 4};
    fill.color = {0.6, 0.7, 1};
    fill.intensity = 25;
    s.lights = {key, fill};
    s.render.maxBounces = 3;
    s.render.ambient = 0.03;
    s.render.background = {0.2, 0.25, 0.3};
    return s;
}


}  // namespace rl

namespace rl {

std::vector<ProbeSpec> probesForExercise(int number) {
    for (const ExerciseInfo& e : allExercises())
        if (e.number == number) return unitProbes(e.id);
    return {};
}

}  // namespace rl
