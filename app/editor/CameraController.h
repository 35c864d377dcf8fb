#pragma once
// The viewport's camera moves, in pixels and seconds: orbit around a point,
// pan, dolly, fly (mouse look + WASD), and framing a box. Distances come
// from the caller (what lies under the cursor) and the scene's size, never
// from a constant in metres, so Sponza (40 m) and the Cornell box (0.5 m)
// move alike. Plain maths, no widget, so it is unit tested.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Mesh.h"

namespace lpv::editor {

class CameraController {
public:
    // Degrees of rotation per pixel of mouse movement (orbit and look).
    static constexpr float kDegreesPerPixel = 0.3f;

    void setCamera(const scene::Camera& camera);
    const scene::Camera& camera() const { return camera_; }
    // Fly speed follows the scene's size: crossing it takes about 5 seconds.
    void setSceneBounds(const scene::Bounds& bounds);
    float flySpeed() const { return flySpeed_; }
    // The scene's diagonal (1 for an empty scene): caps a distance with nothing under the cursor.
    float sceneSize() const { return sceneSize_; }

    // Fraction of the distance to the surface under the cursor that one wheel step moves.
    static constexpr float kDollyFraction = 0.2f;

    // Turns the eye around `pivot` (the point under the cursor; the target
    // when nothing is there): yaw about world up, pitch about the view's
    // right axis. The view turns with the eye, so the pivot stays where it is on the screen.
    void orbitAround(const glm::vec3& pivot, float dxPixels, float dyPixels);
    // Moves eye and target together in the view plane; one pixel moves by one
    // pixel's world size at `depth` along the view (the surface grabbed), or at the target without one.
    void pan(float dxPixels, float dyPixels, int viewportHeight, float depth = 0.0f);
    // Moves the eye along `direction` (the ray through the cursor, normalised)
    // by kDollyFraction of `distance` (to the surface it hits) per step, back
    // by the inverse, never through the surface; the view does not turn, so
    // the point under the cursor stays under it. The target moves onto the
    // view axis at that surface's depth, the focus the next orbit turns about.
    void dollyAlong(float steps, const glm::vec3& direction, float distance);
    // Turns the view direction around the eye (fly mode).
    void look(float dxPixels, float dyPixels);
    // Moves eye and target along the view axes: x right, y world up, z forward.
    // `ahead` (the distance to the surface in front, 0 = unknown) slows it
    // near walls: at most that distance per second, never under 1% of the
    // scene per second, never over flySpeed.
    void fly(const glm::vec3& axes, float seconds, bool fast, float ahead = 0.0f);
    // Places the eye so `box` fills the view, keeping the view direction.
    void frame(const scene::Bounds& box);

private:
    glm::vec3 forward() const;
    scene::Camera camera_;
    float flySpeed_ = 1.0f;
    float sceneSize_ = 1.0f;
};

} // namespace lpv::editor
