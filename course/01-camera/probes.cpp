// The probes of exercise 01-camera: the cases, the double-precision
// expected values, the float32 tolerances and the mistakes the checker names.
#include "checks/probe_toolkit.h"

namespace rl {
namespace {

using namespace probes;
namespace R = ref;

// ---- 01 camera --------------------------------------------------------------------------

std::vector<ProbeSpec> cameraProbes() {
    ProbeSpec offsets{"sampleOffset", "sampleOffset(s, n)", 2};
    for (int n = 1; n <= 4; ++n)
        for (int s = 0; s < n * n; ++s) {
            ProbeCase c;
            c.in[0] = float(s);
            c.in[1] = float(n);
            c.group = n == 1 ? "one sample per pixel" : "n x n samples";
            offsets.cases.push_back(c);
        }
    offsets.expected = [](const ProbeCase& c) {
        glm::dvec2 o = R::sampleOffset(int(f(c, 0)), int(f(c, 1)));
        return ProbeValue{o.x, o.y, 0};
    };
    offsets.tolerance = [](const ProbeCase&) { return std::make_pair(1e-6, 0.0); };  // (a + 0.5)/n: exact to 1 ulp
    offsets.describe = [](const ProbeCase& c) { return "s=" + fmt(f(c, 0)) + " n=" + fmt(f(c, 1)); };
    offsets.mistakes = {
        {"samples sit on the pixel corners", "the offset is the cell CENTRE: (a + 0.5)/n, not a/n",
         [](const ProbeCase& c) {
             int s = int(f(c, 0)), n = int(f(c, 1));
             return ProbeValue{double(s % n) / n, double(s / n) / n, 0};
         }},
        {"x and y of the sample grid are swapped", "a = s % n runs along x, b = s / n along y",
         [](const ProbeCase& c) {
             glm::dvec2 o = R::sampleOffset(int(f(c, 0)), int(f(c, 1)));
             return ProbeValue{o.y, o.x, 0};
         }},
    };

    ProbeSpec rays{"cameraRayDirection",
                   "cameraRayDirection(pixelSample, resolution, fovY, right, up, forward)", 3};
    Random rng(101);
    const glm::vec2 sizes[] = {{640, 480}, {320, 160}, {100, 300}, {1, 1}, {7, 5}};
    for (int k = 0; k < 80; ++k) {
        ProbeCase c;
        glm::vec2 res = sizes[k % 5];
        double jy = std::floor(rng.range(0, res.y)), sy = rng.uniform();
        double jx = std::floor(rng.range(0, res.x)), sx = rng.uniform();
        glm::vec2 px(float(jx + sx), float(jy + sy));
        if (k % 7 == 0) px = glm::vec2(0.5f, 0.5f);                  // bottom-left pixel centre
        if (k % 7 == 1) px = res - glm::vec2(0.5f);                   // top-right pixel centre
        float fov = float(rng.range(0.2, 2.6));
        vec3 forward = rng.unitVector();
        vec3 right = glm::normalize(glm::cross(forward, rng.unitVector()));
        vec3 up = glm::cross(right, forward);
        c.in[0] = px.x, c.in[1] = px.y, c.in[2] = res.x, c.in[3] = res.y, c.in[4] = fov;
        put(c, 8, right);
        put(c, 12, up);
        put(c, 16, forward);
        c.group = res.x == res.y ? "square image" : "non-square image (aspect != 1)";
        rays.cases.push_back(c);
    }
    rays.expected = [](const ProbeCase& c) {
        return value(R::cameraRayDirection({f(c, 0), f(c, 1)}, {f(c, 2), f(c, 3)}, f(c, 4), get(c, 8), get(c, 12),
                                           get(c, 16)));
    };
    // A unit vector: 1e-5 absolute is ~100 ulps of its components (tan and normalize, a few ulps each).
    // GLSL ES 3.00 (section 4.5.1) bounds +, -, * (correctly rounded), / (2.5
    // ulp), inversesqrt (2 ulp), exp and log, and leaves the trigonometric
    // functions' precision undefined. The least precise tan measured on a
    // conforming implementation is SwiftShader's (Chromium without a GPU):
    // 7.6e-5 relative. A relative error e in t = tan(fovY/2) scales the
    // lateral part s of the direction (x, y, 1)/|...|, which moves the unit
    // vector by e s / (1 + s^2) <= e / 2. Allowing e = 2e-4 (2.6 times
    // SwiftShader's) adds 1e-4 to the 1e-5 the float32 arithmetic needs
    // (normalize: 2 ulp of inversesqrt plus a few roundings, ~1e-6). A
    // tenth of a pixel at 640 pixels and 60 degrees (1.6e-3 rad a pixel),
    // while every mistake of the contract moves rays by a pixel or more.
    rays.tolerance = [](const ProbeCase&) { return std::make_pair(1e-5 + 1e-4, 0.0); };
    rays.describe = [](const ProbeCase& c) {
        return "pixel=(" + fmt(f(c, 0)) + ", " + fmt(f(c, 1)) + ") res=" + fmt(f(c, 2)) + "x" + fmt(f(c, 3)) +
               " fovY=" + fmt(f(c, 4));
    };
    // The ray as the contract computes it, with switches for the typical
    // mistakes: the aspect ratio on y, the half angle or the full one (or
    // fovY converted to radians a second time), rows from the top, the pixel
    // centre's +0.5 added to a pixelSample that already holds it, and the
    // direction left unnormalised.
    struct RayMistake {
        bool aspectOnY = false;
        double angleScale = 0.5;
        bool flipY = false;
        double extraOffset = 0;
        bool normalise = true;
    };
    auto rayWith = [](const ProbeCase& c, RayMistake m) {
        double t = std::tan(f(c, 4) * m.angleScale), aspect = f(c, 2) / f(c, 3);
        double x = (2 * (f(c, 0) + m.extraOffset) / f(c, 2) - 1) * t * (m.aspectOnY ? 1.0 : aspect);
        double y = (2 * (f(c, 1) + m.extraOffset) / f(c, 3) - 1) * t * (m.aspectOnY ? aspect : 1.0);
        if (m.flipY) y = -y;
        dvec3 d = x * get(c, 8) + y * get(c, 12) + get(c, 16);
        return value(m.normalise ? glm::normalize(d) : d);
    };
    RayMistake aspectOnY, fullAngle, flipped, radiansTwice, halfPixelTwice, unnormalised;
    aspectOnY.aspectOnY = true;
    fullAngle.angleScale = 1.0;
    flipped.flipY = true;
    radiansTwice.angleScale = 0.5 * R::kPi / 180;
    halfPixelTwice.extraOffset = 0.5;
    unnormalised.normalise = false;
    rays.mistakes = {
        {"the image is squashed: the aspect ratio scales y instead of x",
         "x = (2 (i + sx)/width - 1) tan(fovY/2) * aspect; y has no aspect",
         [=](const ProbeCase& c) { return rayWith(c, aspectOnY); }},
        {"the field of view is twice too wide", "t = tan(fovY / 2): fovY is the FULL vertical angle",
         [=](const ProbeCase& c) { return rayWith(c, fullAngle); }},
        {"the picture is upside down", "row j counts from the BOTTOM: y grows with j",
         [=](const ProbeCase& c) { return rayWith(c, flipped); }},
        {"the view is a telescope: fovY converted to radians a second time",
         "fovY arrives in radians already: t = tan(fovY / 2), no radians()",
         [=](const ProbeCase& c) { return rayWith(c, radiansTwice); }},
        {"the picture is shifted by half a pixel: the pixel centre's 0.5 is added twice",
         "pixelSample already holds the sample offset (i + sx, j + sy): do not add 0.5 again",
         [=](const ProbeCase& c) { return rayWith(c, halfPixelTwice); }},
        {"the ray direction is not unit length", "return normalize(x right + y up + forward)",
         [=](const ProbeCase& c) { return rayWith(c, unnormalised); }},
    };
    rays.groupHints = {{"non-square image (aspect != 1)", "check where the aspect ratio width/height goes"}};
    return {offsets, rays};
}

}  // namespace

RL_UNIT_PROBES { return cameraProbes(); }

}  // namespace rl
