#include "core/scene_transform.h"

namespace rl {

Scene scaledScene(const Scene& scene, double s) {
    Scene out = scene;
    out.camera.position *= s;
    out.camera.target *= s;
    for (Light& l : out.lights) {
        l.position *= s;
        l.intensity *= s * s;
    }
    for (Sphere& sp : out.spheres) {
        sp.center *= s;
        sp.radius *= s;
    }
    return out;
}

Scene translatedScene(const Scene& scene, const glm::dvec3& offset) {
    Scene out = scene;
    out.camera.position += offset;
    out.camera.target += offset;
    for (Light& l : out.lights) l.position += offset;
    for (Sphere& sp : out.spheres) sp.center += offset;
    return out;
}

}  // namespace rl
