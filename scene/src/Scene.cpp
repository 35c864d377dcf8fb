#include "lpv/scene/Scene.h"
#include "lpv/scene/WorldMatrices.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lpv::scene {

glm::mat4 Transform::matrix() const {
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

namespace {

bool hasParent(const std::vector<Object>& objects, std::size_t i) {
    const int parent = objects[i].parent;
    return parent >= 0 && std::size_t(parent) < objects.size();
}

} // namespace

// Multiplied from the root down (parent world times child local), the same
// order worldMatrices() uses, so both give identical floats.
glm::mat4 Scene::worldMatrix(int objectIndex) const {
    if (objectIndex < 0 || std::size_t(objectIndex) >= objects.size())
        return glm::mat4(1.0f);
    // Bounded walk: a cyclic parent chain (rejected by the loader) cannot hang us.
    std::vector<std::size_t> chain{std::size_t(objectIndex)};
    while (hasParent(objects, chain.back()) && chain.size() <= objects.size())
        chain.push_back(std::size_t(objects[chain.back()].parent));
    glm::mat4 m(1.0f);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
        m = m * objects[*it].transform.matrix();
    return m;
}

std::vector<glm::mat4> worldMatrices(const Scene& scene) {
    const std::vector<Object>& objects = scene.objects;
    enum class State : unsigned char { Pending, OnChain, Done };
    std::vector<State> state(objects.size(), State::Pending);
    std::vector<glm::mat4> world(objects.size(), glm::mat4(1.0f));
    std::vector<std::size_t> chain;
    for (std::size_t start = 0; start < objects.size(); ++start) {
        // Up to the first object whose matrix is known (or the root), then back down.
        chain.clear();
        std::size_t i = start;
        while (state[i] == State::Pending) {
            state[i] = State::OnChain;
            chain.push_back(i);
            if (!hasParent(objects, i))
                break;
            i = std::size_t(objects[i].parent);
        }
        // A cycle (i still OnChain), which the loader rejects, is cut where it closes.
        glm::mat4 m = state[i] == State::Done ? world[i] : glm::mat4(1.0f);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            m = m * objects[*it].transform.matrix();
            world[*it] = m;
            state[*it] = State::Done;
        }
    }
    return world;
}

Bounds Scene::worldBounds() const {
    Bounds b;
    const std::vector<glm::mat4> world = worldMatrices(*this);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        if (o.mesh < 0 || std::size_t(o.mesh) >= meshes.size())
            continue;
        const glm::mat4& m = world[i];
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
