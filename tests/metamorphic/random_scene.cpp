#include "metamorphic/random_scene.h"

#include "core/scene_transform.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rl::meta {

using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// SplitMix64 (Steele, Lea, Flood 2014): tiny, seedable, the same everywhere.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1), 53 bits
    double range(double a, double b) { return a + (b - a) * uniform(); }
    int integer(int a, int b) { return a + int(next() % std::uint64_t(b - a + 1)); }  // [a, b]
    bool chance(double p) { return uniform() < p; }
    dvec3 unitVector() {  // uniform on the sphere (Archimedes: z uniform)
        double z = range(-1, 1), phi = range(0, 2 * kPi), s = std::sqrt(std::max(0.0, 1 - z * z));
        return dvec3(s * std::cos(phi), s * std::sin(phi), z);
    }
    dvec3 colour(double lo, double hi) { return dvec3(range(lo, hi), range(lo, hi), range(lo, hi)); }

private:
    std::uint64_t state_;
};

Material randomMaterial(Random& rng, double mirrorChance = 0.2) {
    Material m;
    double u = rng.uniform();
    if (u < mirrorChance) {  // the spec's mirror: roughness at its clamp, metallic 1
        m.albedo = rng.colour(0.6, 1.0);
        m.roughness = 0.045;
        m.metallic = 1;
    } else if (u < mirrorChance + 0.25) {
        m.albedo = rng.colour(0.3, 1.0);
        m.roughness = rng.range(0.05, 0.8);
        m.metallic = 1;
    } else {
        m.albedo = rng.colour(0.05, 0.95);
        m.roughness = rng.chance(0.1) ? 0.0 : rng.range(0.05, 1.0);
        m.metallic = rng.chance(0.1) ? rng.range(0, 1) : 0.0;
    }
    m.ao = rng.chance(0.8) ? 1.0 : rng.range(0.3, 1.0);
    return m;
}

// Distance from p to the surface of s (positive inside or outside).
double surfaceDistance(dvec3 p, const Sphere& s) { return std::abs(glm::length(p - s.center) - s.radius); }
bool insideSphere(dvec3 p, const Sphere& s) { return glm::length(p - s.center) < s.radius; }

// A light at a position drawn by `draw`, at least 1.5 from every surface
// and inside no sphere but `enclosure` (-1: none); false after 200 tries.
template <class Draw>
bool addLight(Scene& scene, Random& rng, Draw draw, int enclosure = -1) {
    for (int attempt = 0; attempt < 200; ++attempt) {
        dvec3 p = draw();
        bool ok = true;
        for (int i = 0; i < int(scene.spheres.size()) && ok; ++i) {
            const Sphere& s = scene.spheres[size_t(i)];
            ok = surfaceDistance(p, s) >= 1.5 && (i == enclosure || !insideSphere(p, s));
        }
        if (!ok) continue;
        Light light;
        light.position = p;
        light.color = rng.chance(0.5) ? dvec3(1.0) : rng.colour(0.4, 1.0);
        light.intensity = rng.range(5, 60);
        scene.lights.push_back(light);
        return true;
    }
    return false;
}

// A camera looking at `target` from a position drawn by `draw`, at least
// `clearance` from every surface and inside no sphere but `enclosure`.
template <class Draw>
bool placeCamera(Scene& scene, Random& rng, dvec3 target, Draw draw, double clearance, int enclosure = -1) {
    for (int attempt = 0; attempt < 200; ++attempt) {
        dvec3 p = draw();
        bool ok = glm::length(target - p) > 0.5;
        for (int i = 0; i < int(scene.spheres.size()) && ok; ++i) {
            const Sphere& s = scene.spheres[size_t(i)];
            ok = surfaceDistance(p, s) >= clearance && (i == enclosure || !insideSphere(p, s));
        }
        // up = +y must not be parallel to the view.
        dvec3 f = glm::normalize(target - p);
        if (!ok || std::abs(f.y) > 0.95) continue;
        scene.camera.position = p;
        scene.camera.target = target;
        scene.camera.up = dvec3(0, 1, 0);
        scene.camera.fovYDegrees = rng.range(35, 65);
        return true;
    }
    return false;
}

void randomSettings(Scene& scene, Random& rng) {
    RenderSettings& r = scene.render;
    r.width = 48;
    r.height = 36;
    r.spp = rng.chance(0.3) ? 4 : 1;
    r.maxBounces = rng.integer(0, 8);
    r.ambient = rng.chance(0.3) ? 0.0 : rng.range(0.0, 0.05);
    r.background = rng.chance(0.3) ? dvec3(0.0) : rng.colour(0.0, 0.8);
    r.exposure = rng.chance(0.7) ? 1.0 : rng.range(0.5, 2.0);
    double u = rng.uniform();
    r.tonemap = u < 0.7 ? ToneMap::Reinhard : u < 0.9 ? ToneMap::Exponential : ToneMap::None;
    r.srgb = rng.chance(0.2);
    r.gamma = 2.2;
}

// n, mostly small: 1..max with a density falling like 1/n.
int fewToMany(Random& rng, int max) { return std::clamp(int(std::exp(rng.range(0, std::log(double(max) + 1)))), 1, max); }

// A sphere of radius r placed relative to the spheres already there: free,
// touching one of them (outside), or overlapping it.
dvec3 clusterCentre(Random& rng, const std::vector<Sphere>& placed, double r, double spread) {
    if (placed.empty() || rng.chance(0.35)) return dvec3(rng.range(-spread, spread), rng.range(-spread, spread), rng.range(-spread, spread));
    const Sphere& other = placed[size_t(rng.integer(0, int(placed.size()) - 1))];
    double gap = rng.chance(0.6) ? 1.0 : rng.range(0.3, 0.9);  // 1: touching, < 1: overlapping
    return other.center + gap * (other.radius + r) * rng.unitVector();
}

Scene clusterScene(Random& rng) {
    Scene scene;
    int count = fewToMany(rng, 64);
    double spread = 0.6 + 0.6 * std::cbrt(double(count));  // free spheres in [-spread, spread]^3: denser when few
    for (int k = 0; k < count; ++k) {
        double r = rng.range(0.15, 1.2);
        scene.spheres.push_back(sphere(clusterCentre(rng, scene.spheres, r, spread), r, randomMaterial(rng)));
    }
    int lights = rng.chance(0.1) ? 0 : fewToMany(rng, 16);
    for (int k = 0; k < lights; ++k)
        addLight(scene, rng, [&] { return dvec3(rng.range(-9, 9), rng.range(-9, 9), rng.range(-9, 9)); });
    return scene;
}

// The centre of a sphere of radius r resting on the ground (centre gc,
// radius R) above the point (x, 0, z) of the plane y = 0 tangent to it.
dvec3 resting(dvec3 gc, double R, double r, double x, double z) {
    return gc + (R + r) * glm::normalize(dvec3(x, 0, z) - gc);
}

Scene groundScene(Random& rng) {
    Scene scene;
    double R = std::pow(10.0, rng.range(2, 5));
    dvec3 gc(0, -R, 0);
    Material ground = randomMaterial(rng, 0.1);
    scene.spheres.push_back(sphere(gc, R, ground));
    int count = fewToMany(rng, 40);
    for (int k = 0; k < count; ++k) {
        double r = rng.range(0.15, 1.0);
        if (scene.spheres.size() > 1 && rng.chance(0.3)) {  // stacked: touching another sphere, above the ground
            const Sphere& other = scene.spheres[size_t(rng.integer(1, int(scene.spheres.size()) - 1))];
            dvec3 dir = rng.unitVector();
            dir.y = std::abs(dir.y) + 0.3;
            scene.spheres.push_back(sphere(other.center + (other.radius + r) * glm::normalize(dir), r, randomMaterial(rng)));
        } else {
            scene.spheres.push_back(sphere(resting(gc, R, r, rng.range(-4, 4), rng.range(-4, 4)), r, randomMaterial(rng)));
        }
    }
    int lights = fewToMany(rng, 16);
    for (int k = 0; k < lights; ++k) {
        if (rng.chance(0.4)) {  // grazing: low over the ground, far away
            double a = rng.range(0, 2 * kPi), d = rng.range(10, 40);
            addLight(scene, rng, [&] {
                dvec3 over(d * std::cos(a), 0, d * std::sin(a));
                return resting(gc, R, rng.range(1.5, 3.0), over.x, over.z);
            });
        } else {
            addLight(scene, rng, [&] { return dvec3(rng.range(-8, 8), rng.range(2, 9), rng.range(-8, 8)); });
        }
    }
    double height = rng.range(0.3, 4.0);
    placeCamera(scene, rng, dvec3(rng.range(-1, 1), rng.range(0, 0.5), rng.range(-1, 1)), [&] {
        double a = rng.range(0, 2 * kPi), d = rng.range(7, 12);
        return resting(gc, R, height, d * std::cos(a), d * std::sin(a));
    }, 0.2);
    return scene;
}

Scene touchingRowsScene(Random& rng) {
    Scene scene;
    double R = std::pow(10.0, rng.range(2, 5));
    dvec3 gc(0, -R, 0);
    scene.spheres.push_back(sphere(gc, R, randomMaterial(rng, 0.1)));
    int total = rng.integer(12, 32);
    int rows = rng.integer(1, 4);
    double r = rng.range(0.2, 0.5);
    double theta = 2 * std::asin(r / (R + r));  // angle between the centres of two touching spheres on the ground
    double psi = rng.range(0, kPi);
    dvec3 along(std::cos(psi), 0, std::sin(psi)), across(-std::sin(psi), 0, std::cos(psi));
    int perRow = (total + rows - 1) / rows;
    for (int k = 0; k < total; ++k) {
        int row = k / perRow, i = k % perRow;
        double alpha = (i - 0.5 * perRow) * theta;
        double beta = (row - 0.5 * rows) * theta * (rng.chance(0.5) ? 1.0 : 1.3);  // rows touching or apart
        dvec3 dir = std::cos(alpha) * std::cos(beta) * dvec3(0, 1, 0) + std::sin(alpha) * along +
                    std::cos(alpha) * std::sin(beta) * across;
        scene.spheres.push_back(sphere(gc + (R + r) * glm::normalize(dir), r, randomMaterial(rng)));
    }
    for (int k = 0; k < 6; ++k)
        addLight(scene, rng, [&] { return dvec3(rng.range(-10, 10), rng.range(1.6, 8), rng.range(-10, 10)); });
    double height = rng.range(0.5, 4.0);
    placeCamera(scene, rng, dvec3(0, r, 0), [&] {
        double a = rng.range(0, 2 * kPi), d = rng.range(6, 10);
        return resting(gc, R, height, d * std::cos(a), d * std::sin(a));
    }, 0.2);
    return scene;
}

Scene enclosedScene(Random& rng) {
    Scene scene;
    double Renc = rng.range(6, 12);
    Material wall = randomMaterial(rng, 0.4);
    scene.spheres.push_back(sphere(dvec3(0.0), Renc, wall));
    int count = fewToMany(rng, 20);
    for (int k = 0; k < count; ++k) {
        double r = rng.range(0.2, 1.5);
        dvec3 c = rng.chance(0.25) ? (Renc - r) * rng.unitVector()  // touching the wall from inside
                                   : rng.range(0, Renc - 2 * r) * rng.unitVector();
        scene.spheres.push_back(sphere(c, r, randomMaterial(rng)));
    }
    int lights = rng.chance(0.15) ? 0 : fewToMany(rng, 16);
    for (int k = 0; k < lights; ++k) addLight(scene, rng, [&] { return rng.range(0, Renc - 1.5) * rng.unitVector(); }, 0);
    placeCamera(scene, rng, rng.range(0, 2) * rng.unitVector(), [&] { return rng.range(0, Renc - 0.5) * rng.unitVector(); },
                0.3, 0);
    return scene;
}

Scene facingMirrorsScene(Random& rng) {
    Scene scene;
    Material mirror;
    mirror.albedo = rng.colour(0.8, 1.0);
    mirror.roughness = 0.045;
    mirror.metallic = 1;
    double r = rng.range(1, 3), gap = rng.range(1, 4);
    scene.spheres.push_back(sphere(dvec3(-(r + 0.5 * gap), 0, 0), r, mirror));
    scene.spheres.push_back(sphere(dvec3(r + 0.5 * gap, 0, 0), r, mirror));
    int extra = rng.integer(0, 6);
    for (int k = 0; k < extra; ++k) {
        double s = rng.range(0.15, 0.6);
        scene.spheres.push_back(sphere(dvec3(rng.range(-gap, gap) * 0.4, rng.range(-2, 2), rng.range(-2, 2)), s,
                                       randomMaterial(rng)));
    }
    int lights = rng.integer(0, 6);
    for (int k = 0; k < lights; ++k)
        addLight(scene, rng, [&] { return dvec3(rng.range(-6, 6), rng.range(-6, 6), rng.range(-6, 6)); });
    placeCamera(scene, rng, dvec3(rng.range(-0.5, 0.5), 0, 0),
                [&] { return dvec3(rng.range(-1, 1), rng.range(-3, 3), rng.range(4, 9)); }, 0.3);
    return scene;
}

Scene distantCameraScene(Random& rng) {
    Scene scene;
    scene.spheres.push_back(sphere(dvec3(0.0), 1.0, randomMaterial(rng)));  // the radius-1 sphere at the origin
    int extra = rng.integer(0, 5);
    for (int k = 0; k < extra; ++k) {
        double r = rng.range(0.1, 0.6);
        scene.spheres.push_back(sphere(clusterCentre(rng, scene.spheres, r, 1.5), r, randomMaterial(rng)));
    }
    int lights = rng.integer(1, 6);
    for (int k = 0; k < lights; ++k)
        addLight(scene, rng, [&] { return dvec3(rng.range(-6, 6), rng.range(-6, 6), rng.range(-6, 6)); });
    double distance = std::pow(10.0, rng.range(3, std::log10(3000.0)));
    placeCamera(scene, rng, dvec3(0.0), [&] {
        dvec3 d = rng.unitVector();
        d.y *= 0.5;
        return distance * glm::normalize(d);
    }, 1.0);
    // Frame a half-height of 1.1 to 2 at the target (the unit sphere fills
    // 15% to 50% of the picture): fov 0.04 to 0.23 degrees.
    scene.camera.fovYDegrees = 2 * std::atan(rng.range(1.1, 2.0) / distance) * 180 / kPi;
    return scene;
}

// Rotation of v by the unit quaternion (w, q).
dvec3 rotate(double w, dvec3 q, dvec3 v) {
    dvec3 t = 2.0 * glm::cross(q, v);
    return v + w * t + glm::cross(q, t);
}

}  // namespace

Sphere sphere(dvec3 centre, double radius, Material m) {
    Sphere s;
    s.center = centre;
    s.radius = radius;
    s.material = m;
    return s;
}

std::string kindName(SceneKind kind) {
    switch (kind) {
        case SceneKind::Cluster: return "cluster";
        case SceneKind::Ground: return "ground";
        case SceneKind::TouchingRows: return "touching-rows";
        case SceneKind::Enclosed: return "enclosed";
        case SceneKind::FacingMirrors: return "facing-mirrors";
        case SceneKind::DistantCamera: return "distant-camera";
    }
    return "?";
}

SceneKind sceneKind(std::uint64_t seed) { return SceneKind(int(seed % 6)); }

Scene randomScene(std::uint64_t seed) {
    Random rng(seed);
    Scene scene;
    SceneKind kind = sceneKind(seed);
    switch (kind) {
        case SceneKind::Cluster: scene = clusterScene(rng); break;
        case SceneKind::Ground: scene = groundScene(rng); break;
        case SceneKind::TouchingRows: scene = touchingRowsScene(rng); break;
        case SceneKind::Enclosed: scene = enclosedScene(rng); break;
        case SceneKind::FacingMirrors: scene = facingMirrorsScene(rng); break;
        case SceneKind::DistantCamera: scene = distantCameraScene(rng); break;
    }
    randomSettings(scene, rng);
    if (kind == SceneKind::TouchingRows) {  // the hard kind: spp 4, no bounces
        scene.render.spp = 4;
        scene.render.maxBounces = 0;
    }
    if (kind == SceneKind::FacingMirrors) scene.render.maxBounces = rng.integer(4, 8);
    if (kind == SceneKind::Cluster) {
        // A camera outside the cluster, looking at its centre from where the
        // cluster's bounding sphere fills 70% to 110% of the picture's height.
        dvec3 centre(0.0);
        for (const Sphere& s : scene.spheres) centre += s.center / double(scene.spheres.size());
        double extent = 0;
        for (const Sphere& s : scene.spheres) extent = std::max(extent, glm::length(s.center - centre) + s.radius);
        double fov = rng.range(35, 65);
        double distance = std::max(extent / std::sin(0.5 * fov * kPi / 180) * rng.range(0.9, 1.4), extent + 0.5);
        placeCamera(scene, rng, centre, [&] { return centre + distance * rng.unitVector(); }, 0.3);
        scene.camera.fovYDegrees = fov;
    }
    scene.sourcePath = "<random " + std::to_string(seed) + ">";
    return scene;
}

std::string describeScene(std::uint64_t seed, const Scene& scene) {
    char text[200];
    std::snprintf(text, sizeof text, "seed %llu (%s): %zu spheres, %zu lights, spp %d, %d bounces",
                  static_cast<unsigned long long>(seed), kindName(sceneKind(seed)).c_str(), scene.spheres.size(),
                  scene.lights.size(), scene.render.spp, scene.render.maxBounces);
    return text;
}

Scene rotatedScene(const Scene& scene, std::uint64_t seed) {
    Random rng(seed ^ 0xA5A5A5A5ull);
    // Uniform random unit quaternion (Shoemake 1992).
    double u1 = rng.uniform(), u2 = rng.range(0, 2 * kPi), u3 = rng.range(0, 2 * kPi);
    double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    double w = a * std::cos(u2);
    dvec3 q(a * std::sin(u2), b * std::sin(u3), b * std::cos(u3));
    Scene out = scene;
    out.camera.position = rotate(w, q, scene.camera.position);
    out.camera.target = rotate(w, q, scene.camera.target);
    out.camera.up = rotate(w, q, scene.camera.up);
    for (Light& l : out.lights) l.position = rotate(w, q, l.position);
    for (Sphere& s : out.spheres) s.center = rotate(w, q, s.center);
    return out;
}

Scene fartherCamera(const Scene& scene, double factor) {
    Scene out = scene;
    out.camera.position = scene.camera.target + factor * (scene.camera.position - scene.camera.target);
    double halfAngle = 0.5 * scene.camera.fovYDegrees * kPi / 180;
    out.camera.fovYDegrees = 2 * std::atan(std::tan(halfAngle) / factor) * 180 / kPi;
    return out;
}

std::string transformName(Transform t) {
    switch (t) {
        case Transform::Identity: return "identity";
        case Transform::Scale: return "scale";
        case Transform::Translate: return "translate";
        case Transform::Rotate: return "rotate";
        case Transform::FartherCamera: return "farther_camera";
    }
    return "?";
}

bool keepsPicture(Transform t) { return t != Transform::FartherCamera; }

Scene transformed(const Scene& scene, Transform t, std::uint64_t seed, std::string* what) {
    Random rng(seed ^ 0x5DEECE66Dull);
    char text[160] = "";
    Scene out = scene;
    switch (t) {
        case Transform::Identity: break;
        case Transform::Scale: {
            double s = std::pow(10.0, rng.range(-6, 6));
            out = scaledScene(scene, s);
            std::snprintf(text, sizeof text, "scale %.3g", s);
            break;
        }
        case Transform::Translate: {
            dvec3 offset = std::pow(10.0, rng.range(0, 6)) * rng.unitVector();
            out = translatedScene(scene, offset);
            std::snprintf(text, sizeof text, "translate (%.4g, %.4g, %.4g)", offset.x, offset.y, offset.z);
            break;
        }
        case Transform::Rotate: {
            out = rotatedScene(scene, seed);
            std::snprintf(text, sizeof text, "rotate (seed %llu)", static_cast<unsigned long long>(seed));
            break;
        }
        case Transform::FartherCamera: {
            double factor = std::min(1000.0, std::tan(0.5 * scene.camera.fovYDegrees * kPi / 180) /
                                                 std::tan(0.5 * kMinFartherFovDegrees * kPi / 180));
            out = fartherCamera(scene, factor);
            std::snprintf(text, sizeof text, "camera %.4gx farther, fov %.3g deg", factor, out.camera.fovYDegrees);
            break;
        }
    }
    if (what) *what = text;
    return out;
}

}  // namespace rl::meta
