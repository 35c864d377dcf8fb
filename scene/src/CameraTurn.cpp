#include "lpv/scene/CameraTurn.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lpv::scene {

Camera yawedAboutUp(const Camera& camera, float degrees) {
    const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
    Camera turned = camera;
    turned.target = camera.position + glm::vec3(rotation * glm::vec4(camera.target - camera.position, 0.0f));
    turned.up = glm::vec3(rotation * glm::vec4(camera.up, 0.0f));
    return turned;
}

} // namespace lpv::scene
