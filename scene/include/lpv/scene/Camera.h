#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace lpv::scene {

struct Camera {
    std::string name;
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = 0.785398f; // radians
    // In metres, for a camera nobody fitted to a scene: one made for an
    // imported or generated scene takes its planes from the scene's bounds
    // (scene::fitClipPlanes and framingCamera, FramingCamera.h; issue #41),
    // since these clip a 2 cm scene whole and cut a 2 km one.
    float nearPlane = 0.05f;
    float farPlane = 500.0f;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;

    bool operator==(const Camera&) const = default;
};

struct CameraKeyframe {
    float time = 0.0f; // seconds
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    float fovY = 0.785398f;

    bool operator==(const CameraKeyframe&) const = default;
};

// Played back through scene::CameraSpline (CameraSpline.h, docs/camera-paths.md).
struct CameraPath {
    std::string name;
    std::vector<CameraKeyframe> keyframes; // sorted by time; equal times make a cut
    // A closed path returns from the last key to the first; the closing
    // segment lasts as long as the mean segment, and time wraps around.
    bool closed = false;
    // Time maps to distance along the path (constant speed over the whole
    // path); the key times then only set the total duration.
    bool constantSpeed = false;

    bool operator==(const CameraPath&) const = default;
};

} // namespace lpv::scene
