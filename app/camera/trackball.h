// The live program's camera: an arcball that orbits the scene camera's target,
// plus pan and dolly. Pure math, no window: the window code turns mouse
// events into calls and uploads cameraToWorld() as u_cameraToWorld.
//
// Window coordinates: framebuffer pixels, origin at the TOP-LEFT corner, x to
// the right, y DOWN (as GLFW reports the cursor; on a HiDPI screen multiply
// the cursor position by framebuffer size / window size first).
//
// Rotation follows Shoemake 1992, "ARCBALL: A User Interface for Specifying
// Three-Dimensional Orientation Using a Mouse": a window point maps to a unit
// sphere drawn over the viewport (points outside its silhouette map to the
// silhouette), and a drag from point p0 to p1 on that sphere turns the scene
// by the quaternion q = [p0 . p1, p0 x p1], i.e. about p0 x p1 by TWICE the
// arc between them. The double angle is Shoemake's: it makes a drag's effect
// depend only on its end points, so a drag that comes back to where it began
// restores the view exactly, and dragging across the whole ball (centre to
// silhouette) turns the scene half a turn. The scene turns; the camera orbits
// the target the opposite way, keeping its distance.
#pragma once

#include "core/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace rl {

class Trackball {
public:
    enum class Mode {
        Rotate,     // left button: orbit about the target (arcball)
        Pan,        // right or middle button: move position and target in the view plane
        Turntable,  // left button, turntable orbit: yaw about the scene's up, pitch about the
                    // camera's right; the horizon stays level (no roll), the pitch stops short
                    // of the poles
    };

    // Throws rl::Error when position == target or up is parallel to the view
    // (the scene loader already refuses such cameras).
    Trackball(const Camera& sceneCamera, int viewportWidth, int viewportHeight);

    // Framebuffer size in pixels; a minimised window (0 x 0) is kept as 1 x 1.
    void setViewport(int width, int height);

    // A drag: every drag() is measured from the beginDrag() point and the
    // camera as it was then, so the path between does not matter.
    void beginDrag(glm::dvec2 windowPixel, Mode mode);
    void drag(glm::dvec2 windowPixel);
    void endDrag();
    bool dragging() const { return dragging_; }

    // Mouse wheel: positive steps move towards the target, each step scaling
    // the distance by kDollyPerStep; the distance stays within
    // [minDistance, maxDistance], so the camera never reaches the target.
    void zoom(double wheelSteps);

    // Back to the scene file's camera (ends any drag).
    void reset();
    // Jumps to `camera` (a named camera of the live view; ends any drag);
    // reset() still goes back to the scene file's; the field of view stays
    // the scene file's. False, and no change,
    // for a camera without a view direction or with up along it.
    bool setView(const Camera& camera);

    // The current view. `up` is orthonormal to the view direction, so the
    // spec's camera formulas give the same basis as cameraToWorld*().
    Camera camera() const;
    // Columns: right, up, back (= -forward: the camera looks down -Z, as in
    // OpenGL), position. Float for the shader's u_cameraToWorld.
    glm::mat4 cameraToWorld() const;
    glm::dmat4 cameraToWorldD() const;

    // Where a window point lands on the arcball, in camera coordinates
    // (x right, y up, z towards the viewer); unit length. Public for tests.
    glm::dvec3 pointOnBall(glm::dvec2 windowPixel) const;

    double distance() const { return distance_; }
    double minDistance() const;  // zoom's limits, see trackball.cpp
    double maxDistance() const { return maxDistance_; }

    // One wheel notch brings the camera 10% closer: 7 notches halve the
    // distance, fine enough to place the camera, quick enough to cross a scene.
    static constexpr double kDollyPerStep = 0.9;
    // Turntable: a drag over the window's height turns half a turn, as a
    // drag across the arcball does; the pitch stays 1 degree off the poles,
    // where yaw about up and the view direction would coincide.
    static constexpr double kTurntablePolarMarginRadians = 0.017453292519943295;

private:
    // Settings from the scene file, restored by reset().
    Camera sceneCamera_;
    int width_ = 1, height_ = 1;

    // The view, in one place: orientation_ takes camera axes to world axes.
    glm::dvec3 target_{0.0};
    double distance_ = 1.0;
    glm::dquat orientation_{1.0, 0.0, 0.0, 0.0};
    double fovYRadians_ = 0.0;
    double minDistance_ = 0.0, maxDistance_ = 0.0;  // from the scene camera's distance

    // The drag in progress: where it began and the view at that moment.
    bool dragging_ = false;
    Mode mode_ = Mode::Rotate;
    glm::dvec2 startPixel_{0.0};
    glm::dvec3 startBallPoint_{0.0, 0.0, 1.0};
    glm::dquat startOrientation_{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 startTarget_{0.0};

    glm::dvec3 position() const;
};

}  // namespace rl
