#pragma once
// Playback of a camera path: a smooth camera through every keyframe
// (docs/camera-paths.md explains the choices).
//
// - Position: centripetal Catmull-Rom (Barry-Goldman knots spaced by the
//   square root of the distance between keys), which never forms cusps or
//   loops inside a segment however unevenly keys are spaced. Open ends use a
//   reflected phantom key, so the camera leaves the first key and reaches the
//   last along the chord. The curve parameter follows time through a
//   monotone cubic (PCHIP), so velocity is continuous at keys.
// - Orientation: cubic Bezier on the unit quaternions (De Casteljau with
//   slerp), control points from the keys' angular velocities (time-weighted
//   like Catmull-Rom), after every key is put in the hemisphere of the one
//   before, so q and -q never cause a flip and each segment turns the short
//   way. Angular velocity is continuous at keys.
// - Field of view: monotone cubic (PCHIP) in time; it never overshoots, so it
//   stays between its neighbouring keys' values and positive.
//
// Times are the keys' own clock: sample(keys.front().time) is the first key.
// Outside [startTime(), endTime()] time clamps (open paths) or wraps (closed).
// Two keys at the same time make a cut: the camera jumps, and the later key
// holds from that time on.
#include "lpv/scene/Camera.h"

#include <cstddef>
#include <vector>

namespace lpv::scene {

class CameraSpline {
  public:
    explicit CameraSpline(const CameraPath& path);

    // Time of the last key minus the first; a closed path adds its closing
    // segment, which lasts as long as the mean segment. 0 for 0 or 1 keys.
    float duration() const { return duration_; }
    float startTime() const { return start_; }
    float endTime() const { return start_ + duration_; }
    bool closed() const { return closed_; }
    bool constantSpeed() const { return constantSpeed_; }
    // Length of the curve through the keys (sum of the arc-length table).
    float length() const { return length_; }
    std::size_t keyCount() const { return keys_.size(); }

    // The camera at `time`; the result's `time` is `time` as passed. With no
    // keys, a default keyframe; with one, that key. Orientation is unit length
    // and sign-continuous along the path (it may be the negated stored key,
    // which is the same rotation).
    CameraKeyframe sample(float time) const;

    // `base` with position, target = position + forward, up and fovY from
    // sample(time); near/far planes and name stay base's. With no keys: base.
    Camera cameraAt(float time, const Camera& base) const;

  private:
    struct Segment {
        std::size_t from = 0, to = 0; // key indices (to wraps to 0 on the closing segment)
        float start = 0.0f;           // time at `from`
        float duration = 0.0f;        // 0: a cut
        // Position: Hermite tangents in curve units (scaled by the knot interval).
        glm::vec3 tangentFrom{0.0f}, tangentTo{0.0f};
        // Curve parameter u(tau) over local time tau in [0, 1]: normalised end slopes.
        float uSlopeFrom = 1.0f, uSlopeTo = 1.0f;
        // Orientation: Bezier control points between the (aligned) end keys.
        glm::quat q0, q1, q2, q3;
        // Field of view: Hermite end slopes times the duration.
        float fovSlopeFrom = 0.0f, fovSlopeTo = 0.0f;
    };
    // One row of the constant-speed table: arc length from the start at
    // local time `tau` of segment `segment`.
    struct ArcSample {
        float length = 0.0f;
        std::size_t segment = 0;
        float tau = 0.0f;
    };

    CameraKeyframe evaluate(std::size_t segment, float tau) const;
    glm::vec3 positionAt(const Segment& s, float tau) const;
    void buildArcTable();

    std::vector<CameraKeyframe> keys_; // orientations normalised and hemisphere-aligned
    std::vector<Segment> segments_;
    std::vector<ArcSample> arcTable_;
    float start_ = 0.0f;
    float duration_ = 0.0f;
    float length_ = 0.0f;
    bool closed_ = false;
    bool constantSpeed_ = false;
};

// A keyframe that reproduces `camera`'s view: orientation from the look-at
// basis (the camera looks down its local -Z with +Y up, as glm::lookAt and
// OpenGL), its fovY, at `time`. When `up` is parallel to the view direction
// the nearest of world +Y / +Z that is not stands in.
CameraKeyframe keyframeFromCamera(const Camera& camera, float time);

// The view direction (local -Z) and up (local +Y) of an orientation.
glm::vec3 forwardOf(const glm::quat& orientation);
glm::vec3 upOf(const glm::quat& orientation);

} // namespace lpv::scene
