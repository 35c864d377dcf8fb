#pragma once
// The built-in Cornell box opened to the sky for the scene-level LPV tests:
// its ceiling's triangles collapsed to a point, so a sun can shine in.
#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"

#include <glm/glm.hpp>

namespace lpv::test {

// The Cornell box project without its ceiling and with one sun travelling
// along `direction` (normalised here).
inline scene::Project openCornellBox(glm::vec3 direction, float intensity = 3.0f) {
    scene::Project project = scene::makeCornellBoxProject();
    scene::Mesh& room = project.scene.meshes[0];
    for (std::size_t t = 0; t + 2 < room.indices.size(); t += 3) {
        bool ceiling = true;
        for (std::size_t j = 0; j < 3; ++j)
            ceiling = ceiling && room.positions[room.indices[t + j]].y > 5.4f;
        if (ceiling)
            room.indices[t + 1] = room.indices[t + 2] = room.indices[t];
    }
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(direction);
    sun.color = glm::vec3(1.0f);
    sun.intensity = intensity;
    project.scene.lights = {sun};
    return project;
}

} // namespace lpv::test
