// Seeded random scenes for the metamorphic suite, and the whole-scene
// transforms under which their picture must not change.
//
// randomScene(seed) is a pure function of the seed (its own 64-bit
// generator, no std:: distributions, so every platform draws the same
// scenes): up to 64 spheres and 16 lights, touching and overlapping spheres,
// large grounds (radius 1e2 to 1e5), dielectrics, metals and mirrors
// (roughness 0.045, metallic 1), 0 to 8 bounces, spp 1 or 4, the camera
// sometimes inside a closed sphere, 48x36 pixels.
//
// Scales: the base scene's objects lie within about 10 of the origin (the
// ground's centre aside), radii 0.1 to 1.5, and every light is at least 1.5
// from every surface: the spec's "a light with d2 <= 1e-12 adds nothing" is
// an absolute threshold, which a light 1 from a surface crosses when the
// scene is scaled by 1e-6.
#pragma once

#include "core/scene.h"

#include <cstdint>
#include <ostream>
#include <string>

namespace rl::meta {

// The budgets of every comparison with the true picture, in one place:
// pixels whose 8-bit display value is off by more than 1/255, and the mean
// difference in 8-bit steps.
constexpr double kReferenceOffBudget = 0.0005;  // the CPU reference: 0.05% of pixels
constexpr double kGlslOffBudget = 0.0025;       // the GLSL (float32): 0.25% of pixels
constexpr double kGlslMeanBudget = 0.1;         // and a mean under 0.1/255

// The kinds of scene the generator mixes, one per seed in turn (seed % 6).
enum class SceneKind {
    Cluster,         // free, touching and overlapping spheres, lights anywhere outside them
    Ground,          // a ground of radius 1e2..1e5 with spheres resting on it (touching), grazing lights
    TouchingRows,    // 12-32 touching spheres on a ground, 6 lights, spp 4, no bounces
    Enclosed,        // the camera inside a closed sphere (sometimes a mirror) with spheres and lights in it
    FacingMirrors,   // two or more mirrors facing each other, up to 8 bounces
    DistantCamera,   // a few spheres seen from 1e3 to 3e3 away through a field of view of 0.04 to 0.23 degrees
};
std::string kindName(SceneKind kind);

Scene randomScene(std::uint64_t seed);
SceneKind sceneKind(std::uint64_t seed);

// A sphere of the given centre, radius and material (for building scenes by hand too).
Sphere sphere(glm::dvec3 centre, double radius, Material m);

// A one-line summary for failure messages: "seed 17 (ground): 23 spheres, 6 lights, spp 4, 0 bounces".
std::string describeScene(std::uint64_t seed, const Scene& scene);

// ---- transforms --------------------------------------------------------------------------------

// Every position and the camera's vectors turned by the rotation whose
// quaternion is drawn from `seed` (uniform over rotations): the same picture.
Scene rotatedScene(const Scene& scene, std::uint64_t seed);

// The camera `factor` times farther from its target, the field of view
// narrowed to frame the same rectangle at the target's distance:
//     tan(fov'/2) = tan(fov/2) / factor
// The picture is NOT the same (the perspective flattens): the transformed
// scene is compared with the oracle of the transformed scene.
Scene fartherCamera(const Scene& scene, double factor);

// The transforms of the suite, drawn per scene from its seed.
enum class Transform { Identity, Scale, Translate, Rotate, FartherCamera };
std::string transformName(Transform t);
inline void PrintTo(Transform t, std::ostream* out) { *out << transformName(t); }  // gtest messages
// Applies t with parameters drawn from `seed` (scale 10^u, u uniform in
// [-6, 6]; translation of length 10^u, u in [0, 6], in a random direction;
// a random rotation; the camera 1000 times farther, or less where the field
// of view would fall below kMinFartherFovDegrees). `what` receives a
// description of the parameters ("scale 3.2e-05").
Scene transformed(const Scene& scene, Transform t, std::uint64_t seed, std::string* what = nullptr);

// The narrowest field of view the farther camera goes to: 0.02 degrees, 9.7e-6
// rad per pixel of a 36-pixel-high picture. The distant-camera scenes start
// at 0.04 to 0.23 degrees; 1000 times narrower, a pixel would be 2e-8 to 1e-7
// rad, about the 6e-8 to which float32 resolves a unit vector's component:
// no float32 shader could frame that picture. They move 2 to 12 times
// farther; every other scene (35 to 65 degrees) the full 1000 times.
constexpr double kMinFartherFovDegrees = 0.02;
// True when t keeps the picture (all but FartherCamera).
bool keepsPicture(Transform t);

}  // namespace rl::meta
