#include "render/scene_constants.h"

#include "core/float_range.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rl {

std::string floatLiteral(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(x));
    std::string literal = text;
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal;
}

std::string vec3Literal(const glm::vec3& v) {
    return "vec3(" + floatLiteral(v.x) + ", " + floatLiteral(v.y) + ", " + floatLiteral(v.z) + ")";
}

namespace {

std::string vec4Literal(const glm::vec4& v) {
    return "vec4(" + floatLiteral(v.x) + ", " + floatLiteral(v.y) + ", " + floatLiteral(v.z) + ", " +
           floatLiteral(v.w) + ")";
}

std::string vec2Literal(float x, float y) { return "vec2(" + floatLiteral(x) + ", " + floatLiteral(y) + ")"; }

template <typename F>
std::string chainOver(const std::string& index, std::size_t count, F&& value) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < count; ++i) values.push_back(value(i));
    return selectChain(index, values);
}

}  // namespace

std::string selectChain(const std::string& index, const std::vector<std::string>& values) {
    if (values.empty()) return "0";
    // Each distinct value once, tested against every index that holds it;
    // the last index's value is the default.
    std::vector<std::string> distinct;
    std::vector<std::vector<std::size_t>> at;
    for (std::size_t i = 0; i < values.size(); ++i) {
        auto it = std::find(distinct.begin(), distinct.end(), values[i]);
        if (it == distinct.end()) {
            distinct.push_back(values[i]);
            at.push_back({i});
        } else {
            at[std::size_t(it - distinct.begin())].push_back(i);
        }
    }
    const std::size_t fallback = std::size_t(std::find(distinct.begin(), distinct.end(), values.back()) - distinct.begin());
    std::string out = "(";
    for (std::size_t d = 0; d < distinct.size(); ++d) {
        if (d == fallback) continue;
        for (std::size_t k = 0; k < at[d].size(); ++k)
            out += (k ? " || (" : "(") + index + ") == " + std::to_string(at[d][k]);
        out += " ? " + distinct[d] + " : ";
    }
    return out + distinct[fallback] + ")";
}

ShaderScene sceneNumbers(const Scene& scene) { return shaderScene(scene, scene.camera.position, sceneAnchor(scene)); }

std::string sphereGeometryMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.sphereGeometry.size(), [&](std::size_t i) { return vec4Literal(n.sphereGeometry[i]); });
}

std::string sphereAnchorCMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.sphereExtra.size(), [&](std::size_t i) { return floatLiteral(n.sphereExtra[i].z); });
}

std::string sphereMaterialMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.sphereSurface.size(), [&](std::size_t i) {
        const glm::vec4 s = n.sphereSurface[i], e = n.sphereExtra[i];
        return "Material(" + vec3Literal(glm::vec3(s)) + ", " + floatLiteral(s.w) + ", " + floatLiteral(e.x) + ", " +
               floatLiteral(e.y) + ")";
    });
}

std::string sphereEdgeTintMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.sphereEdgeTint.size(), [&](std::size_t i) { return vec3Literal(glm::vec3(n.sphereEdgeTint[i])); });
}

std::string lightPositionMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.lightPosition.size(), [&](std::size_t i) { return vec3Literal(glm::vec3(n.lightPosition[i])); });
}

std::string lightIntensityMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.lightIntensity.size(), [&](std::size_t i) { return vec3Literal(glm::vec3(n.lightIntensity[i])); });
}

std::string lightSurfaceMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("k", n.lightSurface.size(),
                     [&](std::size_t k) { return vec2Literal(n.lightSurface[k].x, n.lightSurface[k].y); });
}

std::string cameraSphereMacro(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    return chainOver("i", n.sphereFromCamera.size(),
                     [&](std::size_t i) { return vec2Literal(n.sphereFromCamera[i].x, n.sphereFromCamera[i].y); });
}

namespace {

// Light k's relation to sphere j in the shader's unit, from double.
struct LightSphere {
    glm::dvec3 w;  // L - c
    double C;      // |L - c|^2 - r^2
    bool exact;    // the light-side form decides this pair exactly
};

std::vector<std::vector<LightSphere>> lightSpheres(const Scene& scene) {
    const ShaderScene n = sceneNumbers(scene);
    const double unit = n.unit;
    // The largest distance in the scene, in the shader's unit: the test's
    // products are at most its fourth power.
    glm::dvec3 low(INFINITY), high(-INFINITY);
    for (const Sphere& s : scene.spheres) {
        low = glm::min(low, (s.center - glm::dvec3(s.radius)) / unit);
        high = glm::max(high, (s.center + glm::dvec3(s.radius)) / unit);
    }
    for (const Light& l : scene.lights) {
        low = glm::min(low, l.position / unit);
        high = glm::max(high, l.position / unit);
    }
    const double extent = glm::length(high - low);
    // The test decides the segment's distance p from the centre through
    // E^2 - d2 C = d2 (r^2 - p^2): float32 puts p^2 off by a few u |L - c|^2,
    // where the segment test off the hit point is off by u |c - o|^2. So the
    // light's side only where the light is no farther from the sphere than
    // twice the size of the scene's small spheres (the box of those the
    // shader does not refine), or twice the sphere's diameter: a light far
    // beyond the scene (a grazing sun 30 units off, scenes/hard/
    // ground-1e5-grazing-light.json) moved 0.14% of the pixels' shadow edges.
    glm::dvec3 smallLow(INFINITY), smallHigh(-INFINITY);
    for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
        if (refinesRoots(scene, j) && scene.spheres.size() > 1) continue;
        const Sphere& s = scene.spheres[j];
        smallLow = glm::min(smallLow, (s.center - glm::dvec3(s.radius)) / unit);
        smallHigh = glm::max(smallHigh, (s.center + glm::dvec3(s.radius)) / unit);
    }
    const double smallExtent = smallLow.x <= smallHigh.x ? glm::length(smallHigh - smallLow) : 0.0;
    // A shadow ray starts on a sphere's surface, pushed off it by its
    // rounding: where that surface meets sphere j's (overlapping spheres, a
    // sphere twice in the list, two spheres touching), |c - o|^2 - r^2 near
    // 0 decides, and the light's side computes it as d2 - 2 E + C, rounded at
    // the scale of |L - o|^2, not of the offset (a duplicate's twin was
    // speckled with shadow, scenes/hard/overlapping.json). So the light's
    // side only for a sphere that no other meets or touches, the huge ones
    // (a ground it rests on: the shader refines those) aside.
    std::vector<bool> isolated(scene.spheres.size(), true);
    for (std::size_t j = 0; j < scene.spheres.size(); ++j)
        for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
            if (k == j || (refinesRoots(scene, k) && scene.spheres.size() > 1)) continue;
            const Sphere &a = scene.spheres[j], &b = scene.spheres[k];
            if (glm::length(a.center - b.center) <= (a.radius + b.radius) * (1.0 + 1e-3)) isolated[j] = false;
        }
    std::vector<std::vector<LightSphere>> out(scene.lights.size());
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        const int onSurface = int(n.lightSurface.at(k).x);
        for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
            const Sphere& s = scene.spheres[j];
            LightSphere ls;
            ls.w = (scene.lights[k].position - s.center) / unit;
            const double distance = glm::length(ls.w), r = s.radius / unit;
            ls.C = (distance - r) * (distance + r);
            // Outside by far more than float32 blurs |L - c| (a relative
            // 1e-5 of the radius and of the distance); d2 from a point on
            // any sphere is at least (distance - r)^2 for the segments that
            // matter, and at most extent^2.
            const double gap = distance - r;
            const bool outside = gap > 1e-5 * (distance + r);
            const double smallest = gap * gap, largest = std::max(extent, distance + r);
            const bool inRange = smallest * smallest > 1e-30 && largest * largest * largest * largest < 1e30;
            const bool near = distance <= 2.0 * std::max(smallExtent, 2.0 * r);
            ls.exact = outside && inRange && near && isolated[j] && !refinesRoots(scene, j) && onSurface != int(j);
            out[k].push_back(ls);
        }
    }
    return out;
}

}  // namespace

bool writesSpheresOut(const Scene& scene) {
    return scene.spheres.size() * (scene.lights.size() + 1) <= kWrittenOutTests;
}

bool writesLightsOut(const Scene& scene) { return scene.lights.size() <= kWrittenOutLights; }

std::optional<std::string> shadowStepsMacro(const Scene& scene) {
    if (scene.lights.empty() || scene.spheres.size() < 2 || !writesSpheresOut(scene) || !writesLightsOut(scene))
        return std::nullopt;
    const auto pairs = lightSpheres(scene);
    std::string steps;
    bool any = false;
    for (std::size_t j = 0; j < scene.spheres.size(); ++j) {
        bool everyLight = true;
        for (const auto& light : pairs) everyLight = everyLight && light[j].exact;
        any = any || everyLight;
        steps += (everyLight ? " X(" : " Y(") + std::to_string(j) + ")";
    }
    if (!any) return std::nullopt;
    return steps;
}

std::string lightOccludersArray(const Scene& scene) {
    std::string out;
    for (const auto& light : lightSpheres(scene))
        for (const LightSphere& p : light) out += (out.empty() ? "" : ", ") + vec4Literal(glm::vec4(glm::vec3(p.w), float(p.C)));
    return "vec4[](" + out + ")";
}

}  // namespace rl
