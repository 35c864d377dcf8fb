#include "CameraController.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::editor {
namespace {

// Pitch stops this many degrees short of straight up/down, so lookAt's up vector stays valid.
constexpr float kPitchMarginDegrees = 1.0f;

glm::vec3 rotate(const glm::vec3& v, float degrees, const glm::vec3& axis) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis) * glm::vec4(v, 0.0f));
}

// Rotates `offset` (a direction from a pivot) by yaw about world up and pitch
// about its horizontal right axis, clamping the pitch short of the poles.
glm::vec3 turn(const glm::vec3& offset, float yawDegrees, float pitchDegrees, const glm::vec3& up) {
    glm::vec3 v = rotate(offset, yawDegrees, up);
    const float length = glm::length(v);
    const float current = glm::degrees(std::asin(std::clamp(glm::dot(v / length, up), -1.0f, 1.0f)));
    const float limit = 90.0f - kPitchMarginDegrees;
    const float target = std::clamp(current + pitchDegrees, -limit, limit);
    const glm::vec3 right = glm::normalize(glm::cross(v, up));
    return rotate(v, target - current, right);
}

} // namespace

void CameraController::setCamera(const scene::Camera& camera) { camera_ = camera; }

void CameraController::setSceneBounds(const scene::Bounds& bounds) {
    const float size = bounds.empty() ? 1.0f : glm::length(bounds.size());
    sceneSize_ = std::max(size, 1e-4f);
    flySpeed_ = std::max(size / 5.0f, 0.01f);
}

glm::vec3 CameraController::forward() const { return glm::normalize(camera_.target - camera_.position); }

void CameraController::orbitAround(const glm::vec3& pivot, float dxPixels, float dyPixels) {
    // One rotation for eye and target alike: yaw about world up, then pitch
    // about the turned view's right axis, the view's elevation kept short of the poles.
    const glm::vec3 up = camera_.up;
    const glm::quat yaw = glm::angleAxis(glm::radians(-dxPixels * kDegreesPerPixel), up);
    const glm::vec3 f = yaw * forward();
    const float elevation = glm::degrees(std::asin(std::clamp(glm::dot(f, up), -1.0f, 1.0f)));
    const float limit = 90.0f - kPitchMarginDegrees;
    // The view tilts the other way from the eye: dragging down lifts the eye and lowers the view.
    const float tilted = std::clamp(elevation - dyPixels * kDegreesPerPixel, -limit, limit);
    const glm::vec3 right = glm::normalize(glm::cross(f, up));
    const glm::quat turn = glm::angleAxis(glm::radians(tilted - elevation), right) * yaw;
    camera_.position = pivot + turn * (camera_.position - pivot);
    camera_.target = pivot + turn * (camera_.target - pivot);
}

void CameraController::pan(float dxPixels, float dyPixels, int viewportHeight, float depth) {
    const float distance = depth > 0.0f ? depth : glm::length(camera_.target - camera_.position);
    const float worldPerPixel = 2.0f * distance * std::tan(0.5f * camera_.fovY) / float(std::max(viewportHeight, 1));
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, camera_.up));
    const glm::vec3 up = glm::cross(right, f);
    // The scene follows the mouse: dragging right moves the camera left.
    const glm::vec3 move = worldPerPixel * (-dxPixels * right + dyPixels * up);
    camera_.position += move;
    camera_.target += move;
}

void CameraController::dollyAlong(float steps, const glm::vec3& direction, float distance) {
    if (!(distance > 0.0f))
        return;
    // 1 - 0.8^steps: a step in moves 20% of the way, a step out 25% back, so in-then-out returns.
    const float keep = std::pow(1.0f - kDollyFraction, steps);
    // Never closer to the surface than twice the near plane: it would be clipped.
    const float move = std::min(distance * (1.0f - keep), distance - 2.0f * camera_.nearPlane);
    if (move <= 0.0f && steps > 0.0f)
        return;
    const glm::vec3 f = forward();
    camera_.position += direction * move;
    const float depth = std::max(glm::dot(direction, f) * (distance - move), 2.0f * camera_.nearPlane);
    camera_.target = camera_.position + f * depth;
}

void CameraController::look(float dxPixels, float dyPixels) {
    const glm::vec3 offset = camera_.target - camera_.position;
    camera_.target = camera_.position +
                     turn(offset, -dxPixels * kDegreesPerPixel, -dyPixels * kDegreesPerPixel, camera_.up);
}

void CameraController::fly(const glm::vec3& axes, float seconds, bool fast, float ahead) {
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, camera_.up));
    // Down Sponza's nave at full speed, slowing as a pillar comes close.
    const float speed = ahead > 0.0f ? std::clamp(ahead, 0.01f * sceneSize_, flySpeed_) : flySpeed_;
    const glm::vec3 move =
        (axes.x * right + axes.y * camera_.up + axes.z * f) * speed * seconds * (fast ? 4.0f : 1.0f);
    camera_.position += move;
    camera_.target += move;
}

void CameraController::frame(const scene::Bounds& box) {
    if (box.empty())
        return;
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-3f);
    const float distance = radius / std::sin(0.5f * camera_.fovY);
    const glm::vec3 f = forward();
    camera_.target = box.center();
    camera_.position = camera_.target - f * distance;
    camera_.farPlane = std::max(camera_.farPlane, distance + 4.0f * radius);
}

} // namespace lpv::editor
