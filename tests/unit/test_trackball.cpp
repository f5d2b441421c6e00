// The live camera's math without a window: arcball rotation (Shoemake's
// double angle), pan, dolly and reset, checked against closed forms.
#include "camera/trackball.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>

#include <cmath>
#include <random>

using rl::Camera;
using rl::Trackball;
using Mode = rl::Trackball::Mode;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kW = 800, kH = 600;  // a landscape viewport: the ball's radius is kH / 2
const glm::dvec2 kCentre(kW / 2.0, kH / 2.0);
constexpr double kBallRadius = kH / 2.0;

// An oblique camera, so that no test passes by symmetry alone.
Camera sceneCamera() {
    Camera c;
    c.position = {1.0, 2.0, 4.0};
    c.target = {0.5, -0.25, -1.0};
    c.up = {0.1, 1.0, 0.2};  // not orthogonal to the view: the trackball orthonormalises it
    c.fovYDegrees = 50.0;
    return c;
}

glm::dvec3 forwardOf(const Camera& c) { return glm::normalize(c.target - c.position); }

void expectNear(glm::dvec3 a, glm::dvec3 b, double tolerance, const char* what) {
    EXPECT_LT(glm::length(a - b), tolerance) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                             << b.x << ", " << b.y << ", " << b.z << ")";
}

// Largest deviation of the rotation part of cameraToWorld from R^T R = I, and det R - 1.
double orthonormalityError(const glm::dmat4& m) {
    glm::dmat3 r(m);
    glm::dmat3 g = glm::transpose(r) * r;
    double worst = std::abs(glm::determinant(r) - 1.0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(g[i][j] - (i == j ? 1.0 : 0.0)));
    return worst;
}

// The spec's pinhole camera: the window pixel (top-left origin, y down) where
// world point p appears, for the view cameraToWorld and vertical fov.
glm::dvec2 project(const glm::dmat4& cameraToWorld, double fovYDegrees, glm::dvec3 p) {
    glm::dvec3 c = glm::dvec3(glm::inverse(cameraToWorld) * glm::dvec4(p, 1.0));
    double t = std::tan(glm::radians(fovYDegrees) / 2);
    double pixelsPerUnit = kH / (2 * t);  // the same scale in x and y: pixels are square
    return {kW / 2.0 + pixelsPerUnit * c.x / -c.z, kH / 2.0 - pixelsPerUnit * c.y / -c.z};
}

// The world point seen at window pixel `pixel`, at depth `depth` along -Z.
glm::dvec3 unproject(const glm::dmat4& cameraToWorld, double fovYDegrees, glm::dvec2 pixel, double depth) {
    double t = std::tan(glm::radians(fovYDegrees) / 2);
    double unitsPerPixel = 2 * t / kH;
    glm::dvec3 c((pixel.x - kW / 2.0) * unitsPerPixel * depth, (kH / 2.0 - pixel.y) * unitsPerPixel * depth, -depth);
    return glm::dvec3(cameraToWorld * glm::dvec4(c, 1.0));
}

void dragOnce(Trackball& b, glm::dvec2 from, glm::dvec2 to, Mode mode) {
    b.beginDrag(from, mode);
    b.drag(to);
    b.endDrag();
}

}  // namespace

TEST(Trackball, StartsAtTheSceneCameraWithTheSpecBasis) {
    Camera s = sceneCamera();
    Trackball b(s, kW, kH);
    glm::dvec3 f = forwardOf(s);
    glm::dvec3 r = glm::normalize(glm::cross(f, s.up));
    glm::dvec3 u = glm::cross(r, f);
    glm::dmat4 m = b.cameraToWorldD();
    expectNear(glm::dvec3(m[0]), r, 1e-12, "right");
    expectNear(glm::dvec3(m[1]), u, 1e-12, "up");
    expectNear(glm::dvec3(m[2]), -f, 1e-12, "back");
    expectNear(glm::dvec3(m[3]), s.position, 1e-12, "position");
    EXPECT_EQ(m[3][3], 1.0);
    Camera c = b.camera();
    expectNear(c.position, s.position, 1e-12, "camera().position");
    expectNear(c.target, s.target, 0.0 + 1e-15, "camera().target");
    expectNear(c.up, u, 1e-12, "camera().up is the orthonormalised up");
    EXPECT_EQ(c.fovYDegrees, s.fovYDegrees);
    // The float matrix is the double one, rounded.
    glm::mat4 mf = b.cameraToWorld();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_EQ(mf[i][j], float(m[i][j]));
}

TEST(Trackball, WindowPointsMapToTheBallWithYUp) {
    Trackball b(sceneCamera(), kW, kH);
    expectNear(b.pointOnBall(kCentre), {0, 0, 1}, 1e-15, "centre");
    expectNear(b.pointOnBall(kCentre + glm::dvec2(kBallRadius, 0)), {1, 0, 0}, 1e-15, "right edge of the ball");
    expectNear(b.pointOnBall({kW / 2.0, 0.0}), {0, 1, 0}, 1e-15, "top of the window is +y");
    // Outside the silhouette: the nearest silhouette point (the ball is h/2
    // wide on a landscape viewport, so the window's right edge is outside).
    expectNear(b.pointOnBall({double(kW), kH / 2.0}), {1, 0, 0}, 1e-15, "outside, right");
    expectNear(b.pointOnBall(kCentre + glm::dvec2(1e6, -1e6)), {std::sqrt(0.5), std::sqrt(0.5), 0}, 1e-12, "far outside");
    double s = std::sin(0.3);
    expectNear(b.pointOnBall(kCentre + glm::dvec2(0, kBallRadius * s)), {0, -s, std::cos(0.3)}, 1e-12, "below centre");
}

TEST(Trackball, RotationStaysOrthonormalAfterAThousandRandomDrags) {
    Trackball b(sceneCamera(), kW, kH);
    std::mt19937_64 rng(12345);  // fixed seed: a failure reproduces
    // Drags start and end anywhere, inside and outside the window and the ball.
    std::uniform_real_distribution<double> x(-200.0, kW + 200.0), y(-200.0, kH + 200.0);
    double worst = 0;
    for (int k = 0; k < 1000; ++k) {
        b.beginDrag({x(rng), y(rng)}, Mode::Rotate);
        for (int step = 0; step < 3; ++step) b.drag({x(rng), y(rng)});
        b.endDrag();
        worst = std::max(worst, orthonormalityError(b.cameraToWorldD()));
        Camera c = b.camera();
        glm::dvec3 f = forwardOf(c);
        worst = std::max({worst, std::abs(glm::length(c.up) - 1.0), std::abs(glm::dot(c.up, f))});
    }
    EXPECT_LT(worst, 1e-9);
}

TEST(Trackball, DragFromTheCentreTurnsTheSceneByTwiceTheArc) {
    // Shoemake's arcball: a drag from the centre (p0 = +z) to the ball point
    // at angle theta from it turns the scene by 2 theta about p0 x p1. The
    // world point in front of the target, on the ball, moves in the drag's
    // direction to angle 2 theta; the view direction turns by 2 theta too.
    for (double theta : {0.1, 0.4, kPi / 4, 1.2, kPi / 2 - 1e-3}) {
        for (double phi : {0.0, kPi / 2, 2.5}) {  // drag direction on the screen, counterclockwise from +x
            Trackball b(sceneCamera(), kW, kH);
            glm::dmat4 before = b.cameraToWorldD();
            Camera c0 = b.camera();
            double rho = 0.5;  // any radius: the point is fixed in the world
            glm::dvec3 front = c0.target + rho * glm::dvec3(before[2]);
            glm::dvec2 onScreen(std::cos(phi), std::sin(phi));
            glm::dvec2 to = kCentre + kBallRadius * std::sin(theta) * glm::dvec2(onScreen.x, -onScreen.y);
            dragOnce(b, kCentre, to, Mode::Rotate);

            Camera c1 = b.camera();
            double turned = std::acos(std::clamp(glm::dot(forwardOf(c0), forwardOf(c1)), -1.0, 1.0));
            EXPECT_NEAR(turned, 2 * theta, 1e-7) << "theta " << theta << " phi " << phi;
            glm::dvec3 seen = glm::dvec3(glm::inverse(b.cameraToWorldD()) * glm::dvec4(front, 1.0)) -
                              glm::dvec3(0, 0, -glm::length(c1.target - c1.position));  // relative to the target
            glm::dvec3 expected = rho * glm::dvec3(std::sin(2 * theta) * onScreen, std::cos(2 * theta));
            expectNear(seen, expected, 1e-12, "front point after the drag");
        }
    }
}

TEST(Trackball, ADragAndItsReverseRestoreTheCamera) {
    Trackball b(sceneCamera(), kW, kH);
    Camera c0 = b.camera();
    glm::dmat4 m0 = b.cameraToWorldD();
    const glm::dvec2 a(310, 250), z(590, 120), outside(-150, 700);
    for (Mode mode : {Mode::Rotate, Mode::Pan}) {
        // Within one drag: out and back.
        b.beginDrag(a, mode);
        b.drag(z);
        b.drag(outside);
        b.drag(a);
        b.endDrag();
        // Two drags: a to z, then z to a.
        dragOnce(b, a, outside, mode);
        dragOnce(b, outside, a, mode);
        Camera c = b.camera();
        expectNear(c.position, c0.position, 1e-9, "position");
        expectNear(c.target, c0.target, 1e-9, "target");
        expectNear(c.up, glm::dvec3(m0[1]), 1e-9, "up");
        for (int i = 0; i < 4; ++i) expectNear(glm::dvec3(b.cameraToWorldD()[i]), glm::dvec3(m0[i]), 1e-9, "matrix");
    }
}

TEST(Trackball, RotationKeepsTheTargetAndItsDistance) {
    Camera s = sceneCamera();
    Trackball b(s, kW, kH);
    double d0 = glm::length(s.target - s.position);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> x(0.0, kW), y(0.0, kH);
    for (int k = 0; k < 200; ++k) {
        dragOnce(b, {x(rng), y(rng)}, {x(rng), y(rng)}, Mode::Rotate);
        Camera c = b.camera();
        EXPECT_EQ(c.target, s.target);
        EXPECT_NEAR(glm::length(c.target - c.position), d0, 1e-12 * d0);
        expectNear(forwardOf(c), -glm::dvec3(b.cameraToWorldD()[2]), 1e-12, "forward points at the target");
    }
}

TEST(Trackball, PanMovesPositionAndTargetTogetherAndThePointUnderTheCursorFollows) {
    Camera s = sceneCamera();
    Trackball b(s, kW, kH);
    glm::dmat4 m0 = b.cameraToWorldD();
    double depth = glm::length(s.target - s.position);
    const glm::dvec2 from(120, 470), to(505, 95);  // off-centre, both axes
    glm::dvec3 grabbed = unproject(m0, s.fovYDegrees, from, depth);
    dragOnce(b, from, to, Mode::Pan);

    Camera c = b.camera();
    glm::dvec3 moved = c.target - s.target;
    expectNear(c.position - s.position, moved, 1e-12, "position and target move by the same vector");
    EXPECT_GT(glm::length(moved), 0.1);
    EXPECT_NEAR(glm::dot(moved, forwardOf(s)), 0.0, 1e-12) << "the move lies in the view plane";
    glm::dmat4 m1 = b.cameraToWorldD();
    for (int i = 0; i < 3; ++i) expectNear(glm::dvec3(m1[i]), glm::dvec3(m0[i]), 1e-15, "orientation unchanged");
    glm::dvec2 now = project(m1, s.fovYDegrees, grabbed);
    EXPECT_NEAR(now.x, to.x, 1e-9);
    EXPECT_NEAR(now.y, to.y, 1e-9);
}

TEST(Trackball, ZoomDollies0Point9PerStepAndNeverReachesTheTarget) {
    Camera s = sceneCamera();
    Trackball b(s, kW, kH);
    double d0 = glm::length(s.target - s.position);
    glm::dvec3 f0 = forwardOf(s);
    b.zoom(1);
    EXPECT_NEAR(b.distance(), 0.9 * d0, 1e-15 * d0);
    b.zoom(-1);
    EXPECT_NEAR(b.distance(), d0, 1e-15 * d0);
    b.zoom(0.5);  // trackpads send fractions of a step
    EXPECT_NEAR(b.distance(), std::sqrt(0.9) * d0, 1e-15 * d0);
    b.zoom(-0.5);

    for (int k = 0; k < 10000; ++k) b.zoom(1);  // 0.9^10000 underflows to 0 without the floor
    b.zoom(1e9);
    b.zoom(std::numeric_limits<double>::infinity());  // ignored
    b.zoom(std::numeric_limits<double>::quiet_NaN());  // ignored
    Camera c = b.camera();
    EXPECT_GT(b.distance(), 0.0);
    EXPECT_DOUBLE_EQ(b.distance(), b.minDistance());
    EXPECT_GT(glm::dot(c.target - c.position, f0), 0.0) << "still in front of the target, not past it";
    expectNear(forwardOf(c), f0, 1e-9, "the view direction is unchanged by dolly");
    EXPECT_NEAR(glm::length(c.target - c.position), b.minDistance(), 1e-12);

    b.zoom(-1e9);
    EXPECT_DOUBLE_EQ(b.distance(), b.maxDistance());
    EXPECT_TRUE(std::isfinite(b.camera().position.x));
}

TEST(Trackball, ResetRestoresTheSceneCamera) {
    Camera s = sceneCamera();
    Trackball b(s, kW, kH);
    glm::dmat4 m0 = b.cameraToWorldD();
    dragOnce(b, {100, 100}, {700, 500}, Mode::Rotate);
    dragOnce(b, {400, 300}, {50, 20}, Mode::Pan);
    b.zoom(7);
    b.beginDrag({10, 10}, Mode::Rotate);  // reset in the middle of a drag ends it
    b.reset();
    EXPECT_FALSE(b.dragging());
    b.drag({600, 400});  // no drag in progress: nothing happens
    Camera c = b.camera();
    expectNear(c.position, s.position, 1e-12, "position");
    expectNear(c.target, s.target, 1e-15, "target");
    for (int i = 0; i < 4; ++i) expectNear(glm::dvec3(b.cameraToWorldD()[i]), glm::dvec3(m0[i]), 1e-15, "matrix");
}

TEST(Trackball, ViewportSizeSetsTheBallAndZeroSizeIsHarmless) {
    Trackball b(sceneCamera(), kW, kH);
    b.setViewport(400, 1000);  // portrait: radius 200, centre (200, 500)
    expectNear(b.pointOnBall({200, 300}), {0, 1, 0}, 1e-15, "top of the portrait ball");
    b.setViewport(0, 0);  // a minimised window
    dragOnce(b, {0, 0}, {5, 5}, Mode::Rotate);
    dragOnce(b, {0, 0}, {5, 5}, Mode::Pan);
    glm::dmat4 m = b.cameraToWorldD();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(m[i][j]));
    b.beginDrag({std::nan(""), 1.0}, Mode::Rotate);  // non-finite cursor positions are ignored
    EXPECT_FALSE(b.dragging());
}

TEST(Trackball, DegenerateCamerasAreRefused) {
    Camera same = sceneCamera();
    same.target = same.position;
    EXPECT_THROW(Trackball(same, kW, kH), rl::Error);
    Camera parallel = sceneCamera();
    parallel.up = parallel.target - parallel.position;
    EXPECT_THROW(Trackball(parallel, kW, kH), rl::Error);
}

// ---- turntable orbit ---------------------------------------------------------------------

// After any turntable drag, arcball-rolled start or not, the camera's right
// axis is horizontal (perpendicular to the scene's up): the horizon is level.
TEST(Turntable, NeverRolls) {
    Trackball t(sceneCamera(), kW, kH);
    t.beginDrag(kCentre + glm::dvec2(-200, 50), Mode::Rotate);  // roll it first with the arcball
    t.drag(kCentre + glm::dvec2(150, 200));
    t.endDrag();
    const glm::dvec3 U = glm::normalize(sceneCamera().up);
    std::mt19937 rng(14);  // seeded: the same drags every run
    std::uniform_real_distribution<double> pixel(-400, 400);
    for (int i = 0; i < 20; ++i) {
        t.beginDrag(kCentre, Mode::Turntable);
        t.drag(kCentre + glm::dvec2(pixel(rng), pixel(rng)));
        t.endDrag();
        const Camera c = t.camera();
        const glm::dvec3 right = glm::normalize(glm::cross(forwardOf(c), c.up));
        EXPECT_NEAR(glm::dot(right, U), 0.0, 1e-12) << "drag " << i << ": the right axis left the horizon";
        EXPECT_GT(glm::dot(c.up, U), 0.0) << "drag " << i << ": upside down";
        EXPECT_NEAR(glm::length(c.target - c.position), glm::length(sceneCamera().target - sceneCamera().position),
                    1e-9);
    }
}

// A horizontal drag over the window's height turns the camera half a turn
// about the scene's up, keeping its elevation; the direction of the turn
// makes the scene follow the cursor (a point in front of the target moves right).
TEST(Turntable, HorizontalDragYawsAboutUp) {
    Camera level;
    level.position = {0, 0, 4};
    level.target = {0, 0, 0};
    level.up = {0, 1, 0};
    level.fovYDegrees = 50;
    Trackball t(level, kW, kH);
    t.beginDrag(kCentre, Mode::Turntable);
    t.drag(kCentre + glm::dvec2(kH / 4.0, 0));  // a quarter of the height: 45 degrees
    const Camera c = t.camera();
    expectNear(c.position, glm::dvec3(-4 * std::sin(kPi / 4), 0, 4 * std::cos(kPi / 4)), 1e-9,
               "the camera orbits left, so the scene turns right");
    t.drag(kCentre + glm::dvec2(0, -kH));  // up by the whole height: pitch stops at the pole margin
    const double elevation = std::asin(glm::dot(forwardOf(t.camera()), glm::dvec3(0, 1, 0)));
    EXPECT_NEAR(elevation, kPi / 2 - Trackball::kTurntablePolarMarginRadians, 1e-9);
}
