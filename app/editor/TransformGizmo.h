#pragma once
// The move/rotate/scale gizmo: three axis handles drawn from the selected
// object's pivot, in screen space. This file holds the geometry and the
// drag maths (no widget, unit tested); the viewport paints and feeds mouse
// positions.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>

namespace lpv::editor {

enum class GizmoMode { Move, Rotate, Scale };

struct GizmoSnap {
    bool enabled = false;
    float moveStep = 0.25f;    // world units
    float rotateDegrees = 15.0f;
    float scaleStep = 0.1f;
};

class TransformGizmo {
public:
    // Handle length on screen.
    static constexpr float kHandlePixels = 90.0f;
    // A click this close to a handle's line grabs it.
    static constexpr float kGrabPixels = 7.0f;

    // Places the gizmo at `pivot` (world) as seen by `camera` in a width x height view.
    void place(const glm::vec3& pivot, const scene::Camera& camera, int width, int height);
    bool visible() const { return visible_; }
    // Screen position (pixels, y down) of the pivot and of each axis handle's end.
    glm::vec2 pivotScreen() const { return pivotScreen_; }
    glm::vec2 handleEnd(int axis) const { return pivotScreen_ + axisScreen_[std::size_t(axis)] * kHandlePixels; }

    // The axis (0 x, 1 y, 2 z) whose handle lies under `mouse`, if any.
    std::optional<int> hitTest(const glm::vec2& mouse) const;

    // The transform after dragging handle `axis` from `start` to `now` (pixels),
    // starting from `original`. Moves and rotations are along/about world axes.
    scene::Transform drag(GizmoMode mode, int axis, const scene::Transform& original, const glm::vec2& start,
                          const glm::vec2& now, const GizmoSnap& snap) const;

private:
    bool visible_ = false;
    glm::vec2 pivotScreen_{0.0f};
    std::array<glm::vec2, 3> axisScreen_{}; // unit screen direction of each world axis
    std::array<float, 3> worldPerPixel_{};  // world length of one pixel along each axis
};

} // namespace lpv::editor
