#pragma once
#include "lpv/scene/Camera.h"
#include "lpv/scene/Light.h"
#include "lpv/scene/Material.h"
#include "lpv/scene/Mesh.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace lpv::scene {

struct Transform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;

    bool operator==(const Transform&) const = default;
};

// A coarser version of an object's mesh, used from `distance` on. Imported
// and stored (4ds LOD 1..n) but not drawn yet: the renderer draws `mesh`.
struct LodLevel {
    int mesh = -1;
    float distance = 0.0f;

    bool operator==(const LodLevel&) const = default;
};

// A node of the scene graph; mesh and parent are indices (-1 = none).
struct Object {
    std::string name;
    int mesh = -1;
    int parent = -1;
    Transform transform;
    bool visible = true;
    std::vector<LodLevel> lods; // further LODs by increasing distance

    bool operator==(const Object&) const = default;
};

struct Sky {
    glm::vec3 color{0.5f, 0.7f, 1.0f};
    float intensity = 1.0f; // 0 = no sky light (closed interiors)

    bool operator==(const Sky&) const = default;
};

struct Scene {
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Object> objects;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<CameraPath> cameraPaths;
    Sky sky;

    // World matrix of an object, following its parent chain.
    glm::mat4 worldMatrix(int objectIndex) const;
    Bounds worldBounds() const;
    std::size_t triangleCount() const;
    const Camera* findCamera(const std::string& name) const;

    bool operator==(const Scene&) const = default;
};

} // namespace lpv::scene
