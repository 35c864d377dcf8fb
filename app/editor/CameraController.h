#pragma once
// The viewport's camera moves, in pixels and seconds: orbit around the
// target, pan, dolly, fly (mouse look + WASD), and framing a box. Plain
// maths, no widget, so it is unit tested.
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

    // Turns the eye around the target (yaw about world up, pitch about the view's right axis).
    void orbit(float dxPixels, float dyPixels);
    // Moves eye and target together in the view plane; one pixel moves by one pixel's world size at the target.
    void pan(float dxPixels, float dyPixels, int viewportHeight);
    // Moves the eye towards the target by a fraction per wheel step (never through it).
    void dolly(float steps);
    // Turns the view direction around the eye (fly mode).
    void look(float dxPixels, float dyPixels);
    // Moves eye and target along the view axes: x right, y world up, z forward.
    void fly(const glm::vec3& axes, float seconds, bool fast);
    // Places the eye so `box` fills the view, keeping the view direction.
    void frame(const scene::Bounds& box);

private:
    glm::vec3 forward() const;
    scene::Camera camera_;
    float flySpeed_ = 1.0f;
};

} // namespace lpv::editor
