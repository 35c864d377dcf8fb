#include "TransformGizmo.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::editor {
namespace {

std::optional<glm::vec2> toScreen(const glm::mat4& viewProj, const glm::vec3& p, int width, int height) {
    const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f)
        return std::nullopt; // behind the eye
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height));
}

float distanceToSegment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-6f), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

float snapTo(float value, float step) { return step > 0.0f ? std::round(value / step) * step : value; }

} // namespace

void TransformGizmo::place(const glm::vec3& pivot, const scene::Camera& camera, int width, int height) {
    const glm::mat4 viewProj = camera.projection(float(width) / float(std::max(height, 1))) * camera.view();
    const auto centre = toScreen(viewProj, pivot, width, height);
    visible_ = centre.has_value();
    if (!visible_)
        return;
    pivotScreen_ = *centre;
    // Probe each axis with a short world step sized to the distance, then scale to pixels.
    const float probe = 0.05f * std::max(glm::length(pivot - camera.position), 1e-3f);
    for (int a = 0; a < 3; ++a) {
        glm::vec3 step(0.0f);
        step[a] = probe;
        const auto end = toScreen(viewProj, pivot + step, width, height);
        const glm::vec2 d = end ? *end - pivotScreen_ : glm::vec2(0.0f);
        const float pixels = glm::length(d);
        // An axis pointing at the eye has no screen direction: it cannot be grabbed.
        axisScreen_[std::size_t(a)] = pixels > 1e-3f ? d / pixels : glm::vec2(0.0f);
        worldPerPixel_[std::size_t(a)] = pixels > 1e-3f ? probe / pixels : 0.0f;
    }
}

std::optional<int> TransformGizmo::hitTest(const glm::vec2& mouse) const {
    if (!visible_)
        return std::nullopt;
    std::optional<int> best;
    float bestDistance = kGrabPixels;
    for (int a = 0; a < 3; ++a) {
        if (axisScreen_[std::size_t(a)] == glm::vec2(0.0f))
            continue;
        const float d = distanceToSegment(mouse, pivotScreen_, handleEnd(a));
        if (d <= bestDistance) {
            bestDistance = d;
            best = a;
        }
    }
    return best;
}

scene::Transform keepPivotFixed(const scene::Transform& original, scene::Transform changed,
                                const glm::vec3& pivot) {
    // The pivot in the object's own space (its scale never reaches zero: drag keeps 1%).
    const glm::vec3 local = glm::vec3(glm::inverse(original.matrix()) * glm::vec4(pivot, 1.0f));
    const glm::vec3 moved = glm::vec3(changed.matrix() * glm::vec4(local, 1.0f));
    changed.translation += pivot - moved;
    return changed;
}

scene::Transform TransformGizmo::drag(GizmoMode mode, int axis, const scene::Transform& original,
                                      const glm::vec2& start, const glm::vec2& now, const GizmoSnap& snap,
                                      const std::optional<glm::vec3>& pivot) const {
    scene::Transform t = original;
    const glm::vec2 dir = axisScreen_[std::size_t(axis)];
    const glm::vec2 delta = now - start;
    // Mouse travel along the handle's screen direction, in pixels.
    const float along = glm::dot(delta, dir);
    switch (mode) {
    case GizmoMode::Move: {
        float distance = along * worldPerPixel_[std::size_t(axis)];
        if (snap.enabled)
            distance = snapTo(original.translation[axis] + distance, snap.moveStep) - original.translation[axis];
        t.translation[axis] += distance;
        break;
    }
    case GizmoMode::Rotate: {
        // Travel across the handle turns about it: half a degree per pixel.
        const glm::vec2 across{-dir.y, dir.x};
        float degrees = 0.5f * glm::dot(delta, across);
        if (snap.enabled)
            degrees = snapTo(degrees, snap.rotateDegrees);
        glm::vec3 worldAxis(0.0f);
        worldAxis[axis] = 1.0f;
        t.rotation = glm::normalize(glm::angleAxis(glm::radians(degrees), worldAxis) * original.rotation);
        break;
    }
    case GizmoMode::Scale: {
        // One handle length of travel doubles the scale; never below 1% of the original.
        float factor = std::max(1.0f + along / kHandlePixels, 0.01f);
        float scaled = original.scale[axis] * factor;
        if (snap.enabled)
            scaled = std::max(snapTo(scaled, snap.scaleStep), snap.scaleStep);
        t.scale[axis] = scaled;
        break;
    }
    }
    if (mode != GizmoMode::Move && pivot)
        t = keepPivotFixed(original, t, *pivot);
    return t;
}

} // namespace lpv::editor
