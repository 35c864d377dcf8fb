#include "lpv/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lpv::scene {

glm::mat4 Transform::matrix() const {
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::mat4 Scene::worldMatrix(int objectIndex) const {
    glm::mat4 m(1.0f);
    // Bounded walk: a cyclic parent chain (rejected by the loader) cannot hang us.
    for (std::size_t guard = 0; objectIndex >= 0 && std::size_t(objectIndex) < objects.size() &&
                                guard <= objects.size();
         ++guard) {
        const Object& o = objects[std::size_t(objectIndex)];
        m = o.transform.matrix() * m;
        objectIndex = o.parent;
    }
    return m;
}

Bounds Scene::worldBounds() const {
    Bounds b;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        if (o.mesh < 0 || std::size_t(o.mesh) >= meshes.size())
            continue;
        const glm::mat4 m = worldMatrix(int(i));
        const Bounds local = meshes[std::size_t(o.mesh)].computeBounds();
        if (local.empty())
            continue;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                              (corner & 4) ? local.max.z : local.min.z);
            b.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
        }
    }
    return b;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Object& o : objects)
        if (o.mesh >= 0 && std::size_t(o.mesh) < meshes.size())
            n += meshes[std::size_t(o.mesh)].triangleCount();
    return n;
}

const Camera* Scene::findCamera(const std::string& name) const {
    for (const Camera& c : cameras)
        if (c.name == name)
            return &c;
    return nullptr;
}

} // namespace lpv::scene
