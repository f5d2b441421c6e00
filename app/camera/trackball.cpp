// Arcball rotation, pan and dolly of the live view (see trackball.h).
#include "camera/trackball.h"

#include "core/error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

// The dolly limits, relative to the scene camera's distance to its target, so
// that a scene scaled by 1e-3 or 1e3 (which the spec says renders the same)
// also handles the same. A thousandth: closer than that the view is inside
// any sphere around the target worth looking at. A thousand times: the whole
// scene is then a few pixels wide, and further only wastes float precision.
constexpr double kMinDistanceFraction = 1e-3;
constexpr double kMaxDistanceFactor = 1e3;

// A second floor on the distance, relative to |target|: target - position
// must stay resolvable in double (relative spacing 2.2e-16) to about 1e-7,
// so that camera()'s position and target give the same forward as the
// orientation does, even for a target far from the origin.
constexpr double kTargetPrecision = 1e-9;

// Cameras with up this close to parallel to the view direction have no
// defined roll; the same threshold as the scene loader's check.
constexpr double kParallelUpTolerance = 1e-9;

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

Trackball::Trackball(const Camera& sceneCamera, int viewportWidth, int viewportHeight)
    : sceneCamera_(sceneCamera) {
    glm::dvec3 toTarget = sceneCamera.target - sceneCamera.position;
    double distance = glm::length(toTarget);
    if (!(distance > 0.0) || !std::isfinite(distance))
        throw Error("trackball: camera position and target must differ");
    glm::dvec3 side = glm::cross(toTarget / distance, sceneCamera.up);
    if (!(glm::length(side) > kParallelUpTolerance * glm::length(sceneCamera.up)))
        throw Error("trackball: camera up must not be zero or parallel to the viewing direction");
    setViewport(viewportWidth, viewportHeight);
    reset();
}

void Trackball::setViewport(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

void Trackball::reset() {
    const Camera& c = sceneCamera_;
    const double distance = glm::length(c.target - c.position);
    minDistance_ = kMinDistanceFraction * distance;
    maxDistance_ = kMaxDistanceFactor * distance;
    setView(c);
}

bool Trackball::setView(const Camera& c) {
    // The spec's basis: f = normalize(target - position), r = normalize(cross(f, up)), u = cross(r, f).
    const glm::dvec3 toTarget = c.target - c.position;
    const double distance = glm::length(toTarget);
    if (!(distance > 0.0) || !std::isfinite(distance)) return false;
    glm::dvec3 f = toTarget / distance;
    glm::dvec3 side = glm::cross(f, c.up);
    if (!(glm::length(side) > kParallelUpTolerance * glm::length(c.up))) return false;
    glm::dvec3 r = glm::normalize(side);
    glm::dvec3 u = glm::cross(r, f);
    orientation_ = glm::normalize(glm::quat_cast(glm::dmat3(r, u, -f)));
    target_ = c.target;
    distance_ = distance;
    fovYRadians_ = glm::radians(sceneCamera_.fovYDegrees);  // the field of view stays the scene's
    dragging_ = false;
    return true;
}

glm::dvec3 Trackball::pointOnBall(glm::dvec2 windowPixel) const {
    // The ball is the largest circle that fits the viewport, centred on it:
    // the whole ball is reachable and its silhouette is the shorter edge.
    double radius = 0.5 * std::min(width_, height_);
    glm::dvec2 p((windowPixel.x - 0.5 * width_) / radius,
                 (0.5 * height_ - windowPixel.y) / radius);  // window y points down, ball y up
    double r2 = glm::dot(p, p);
    if (r2 > 1.0) {  // outside the silhouette: the nearest point on it
        p /= std::sqrt(r2);
        return glm::dvec3(p, 0.0);
    }
    return glm::dvec3(p, std::sqrt(1.0 - r2));
}

void Trackball::beginDrag(glm::dvec2 windowPixel, Mode mode) {
    if (!finite(windowPixel)) return;
    dragging_ = true;
    mode_ = mode;
    startPixel_ = windowPixel;
    startBallPoint_ = pointOnBall(windowPixel);
    startOrientation_ = orientation_;
    startTarget_ = target_;
}

void Trackball::drag(glm::dvec2 windowPixel) {
    if (!dragging_ || !finite(windowPixel)) return;
    if (mode_ == Mode::Turntable) {
        // Elevation e and heading about U (the scene file's up): a move of
        // (dx, dy) pixels turns the scene by dx pi/height about U and tilts it
        // by dy pi/height about the camera's right, so the point under the
        // cursor follows it (the camera turns the other way). The camera's up
        // is rebuilt from U every time: no roll, whatever the start was.
        const double perPixel = 3.14159265358979323846 / height_;
        const glm::dvec2 moved = windowPixel - startPixel_;
        const glm::dvec3 U = glm::normalize(sceneCamera_.up);
        const glm::dvec3 f0 = startOrientation_ * glm::dvec3(0.0, 0.0, -1.0);
        glm::dvec3 heading = f0 - glm::dot(f0, U) * U;
        if (glm::length(heading) < kParallelUpTolerance)  // looking straight along U: head along the camera's up
            heading = startOrientation_ * glm::dvec3(0.0, glm::dot(f0, U) > 0 ? -1.0 : 1.0, 0.0);
        heading = glm::normalize(heading - glm::dot(heading, U) * U);
        const double limit = 0.5 * 3.14159265358979323846 - kTurntablePolarMarginRadians;
        const double elevation =
            std::clamp(std::asin(std::clamp(glm::dot(f0, U), -1.0, 1.0)) - moved.y * perPixel, -limit, limit);
        heading = glm::angleAxis(-moved.x * perPixel, U) * heading;
        const glm::dvec3 f = std::cos(elevation) * heading + std::sin(elevation) * U;
        const glm::dvec3 r = glm::normalize(glm::cross(f, U));
        const glm::dvec3 u = glm::cross(r, f);
        orientation_ = glm::normalize(glm::quat_cast(glm::dmat3(r, u, -f)));
    } else if (mode_ == Mode::Rotate) {
        // Shoemake's q = [p0 . p1, p0 x p1]: unit for unit p0, p1, and a turn
        // about p0 x p1 by twice the arc from p0 to p1. It turns the scene as
        // seen from the camera; the camera turns the other way, by conj(q)
        // applied in camera coordinates (on the right).
        glm::dvec3 p0 = startBallPoint_;
        glm::dvec3 p1 = pointOnBall(windowPixel);
        glm::dvec3 axis = glm::cross(p0, p1);
        glm::dquat q(glm::dot(p0, p1), axis.x, axis.y, axis.z);
        orientation_ = glm::normalize(startOrientation_ * glm::conjugate(q));
    } else {
        // At the target distance the view is 2 d tan(fovY/2) high over
        // height_ pixels. Moving the camera against the cursor by that much
        // per pixel keeps the point under the cursor (at that depth) under it.
        double worldPerPixel = 2.0 * distance_ * std::tan(0.5 * fovYRadians_) / height_;
        glm::dvec2 moved = windowPixel - startPixel_;
        glm::dvec3 right = orientation_ * glm::dvec3(1.0, 0.0, 0.0);
        glm::dvec3 up = orientation_ * glm::dvec3(0.0, 1.0, 0.0);
        target_ = startTarget_ + worldPerPixel * (-moved.x * right + moved.y * up);  // window y is down
    }
}

void Trackball::endDrag() { dragging_ = false; }

void Trackball::zoom(double wheelSteps) {
    if (!std::isfinite(wheelSteps)) return;
    // Multiplicative: distance * 0.9^steps is never 0 in exact arithmetic;
    // the clamp keeps it so in floating point as well.
    double scaled = distance_ * std::pow(kDollyPerStep, wheelSteps);
    distance_ = std::max(std::min(scaled, maxDistance_), minDistance());  // the floor wins: never at the target
}

double Trackball::minDistance() const {
    return std::max(minDistance_, kTargetPrecision * glm::length(target_));  // pan may have moved the target
}

glm::dvec3 Trackball::position() const { return target_ + distance_ * (orientation_ * glm::dvec3(0.0, 0.0, 1.0)); }

Camera Trackball::camera() const {
    Camera c;
    c.position = position();
    c.target = target_;
    c.up = orientation_ * glm::dvec3(0.0, 1.0, 0.0);
    c.fovYDegrees = sceneCamera_.fovYDegrees;
    return c;
}

glm::dmat4 Trackball::cameraToWorldD() const {
    glm::dmat4 m(glm::mat3_cast(orientation_));  // columns: right, up, back
    m[3] = glm::dvec4(position(), 1.0);
    return m;
}

glm::mat4 Trackball::cameraToWorld() const { return glm::mat4(cameraToWorldD()); }

}  // namespace rl
