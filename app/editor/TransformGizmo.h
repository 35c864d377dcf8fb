#pragma once
// The move/rotate/scale gizmo: three axis handles drawn from the selected
// object's pivot (its bounds centre or its origin, GizmoPivot), in screen
// space. This file holds the geometry and the drag maths (no widget, unit
// tested); the viewport paints and feeds mouse positions.
#include "lpv/scene/Camera.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>

namespace lpv::editor {

enum class GizmoMode { Move, Rotate, Scale };

// Where the gizmo sits and what rotate and scale turn about, as Blender's
// pivot point: the selection's bounds centre (the default: an imported
// object's origin is often a corner, or the world origin) or its origin.
enum class GizmoPivot { BoundsCentre, Origin };

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
    // Rotate and scale keep the object's point at `pivot` (in the space of the
    // object's parent) where it is; without one they turn about the origin.
    scene::Transform drag(GizmoMode mode, int axis, const scene::Transform& original, const glm::vec2& start,
                          const glm::vec2& now, const GizmoSnap& snap,
                          const std::optional<glm::vec3>& pivot = std::nullopt) const;

private:
    bool visible_ = false;
    glm::vec2 pivotScreen_{0.0f};
    std::array<glm::vec2, 3> axisScreen_{}; // unit screen direction of each world axis
    std::array<float, 3> worldPerPixel_{};  // world length of one pixel along each axis
};

// `changed` (a rotation or scale of `original`) moved so that the point of
// the object that lay at `pivot` (parent space) under `original` lies there
// still: turning about the bounds centre instead of the origin.
scene::Transform keepPivotFixed(const scene::Transform& original, scene::Transform changed,
                                const glm::vec3& pivot);

} // namespace lpv::editor
