// The embedded default scene: what `raylab render` draws with no scene file.
// The same as scenes/lecture.json, so a new user sees every feature at once:
// a large-sphere ground, dielectrics and metals from rough to polished,
// two lights with shadows, and mirror bounces.
#include "core/scene_io.h"

namespace rl {

const char* defaultSceneJson() {
    return R"JSON({
  "camera":  { "position": [0, 1.1, 2.2], "target": [0, 0.45, -2.6], "up": [0, 1, 0], "fov_y": 50 },
  "render":  { "width": 640, "height": 480, "max_bounces": 2, "spp": 1, "ambient": 0.03,
               "background": [0.05, 0.07, 0.12], "exposure": 1.0, "tonemap": "reinhard", "gamma": 2.2 },
  "lights":  [ { "position": [-3, 4, 0.5], "color": [1, 0.95, 0.9], "intensity": 40 },
               { "position": [3, 2.5, -1], "color": [0.6, 0.7, 1], "intensity": 15 } ],
  "spheres": [
    { "center": [0, -1000, -3], "radius": 1000,
      "material": { "albedo": [0.55, 0.55, 0.5], "roughness": 0.9, "metallic": 0.0 } },
    { "center": [-1.7, 0.5, -3.2], "radius": 0.5,
      "material": { "albedo": [1.0, 0.77, 0.34], "roughness": 0.25, "metallic": 1.0 } },
    { "center": [-0.55, 0.5, -3.4], "radius": 0.5,
      "material": { "albedo": [0.9, 0.1, 0.1], "roughness": 0.8, "metallic": 0.0 } },
    { "center": [0.6, 0.5, -3.2], "radius": 0.5,
      "material": { "albedo": [0.1, 0.3, 0.9], "roughness": 0.3, "metallic": 0.0 } },
    { "center": [1.75, 0.5, -3.0], "radius": 0.5,
      "material": { "albedo": [0.95, 0.95, 0.95], "roughness": 0.05, "metallic": 1.0 } },
    { "center": [0.05, 0.25, -2.2], "radius": 0.25,
      "material": { "albedo": [0.2, 0.8, 0.3], "roughness": 0.5, "metallic": 0.0 } }
  ]
})JSON";
}

}  // namespace rl
