#include "lpv/scene/Camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lpv::scene {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection(float aspect) const { return glm::perspective(fovY, aspect, nearPlane, farPlane); }

} // namespace lpv::scene
