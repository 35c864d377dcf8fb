#pragma once
// Primary rays through a camera's image plane, as the rasteriser samples it
// (inverse view-projection, near plane to far plane). A camera with a NaN
// field, an up vector along its view or planes that overflow makes a NaN
// inverse; every ray is checked, so such a camera yields no ray rather than
// one that Embree asserts on (issue #42).
#include "lpv/scene/Camera.h"

#include <glm/glm.hpp>

#include <optional>

namespace lpv::reference {

struct CameraRay {
    glm::vec3 origin{0.0f};    // on the near plane
    glm::vec3 direction{0.0f}; // unit
    float length = 0.0f;       // to the far plane
};

class CameraRays {
  public:
    CameraRays() = default;
    CameraRays(const scene::Camera& camera, float aspect);

    // Through normalised device coordinates (x right, y up, -1..1); nothing
    // when the ray would not be finite or Embree would refuse it.
    std::optional<CameraRay> through(float ndcX, float ndcY) const;

  private:
    glm::mat4 inverseViewProjection_{1.0f};
};

} // namespace lpv::reference
