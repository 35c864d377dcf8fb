#pragma once
// Which object a ray hits first (the editor's click selection). On the CPU:
// per object a world-bounds test, then its triangles (Möller–Trumbore);
// a click on Sponza's 262k triangles takes milliseconds, no GPU read-back needed.
#include "lpv/scene/Scene.h"

#include <optional>

namespace lpv::scene {

struct PickHit {
    int object = -1;
    float distance = 0.0f; // along the normalised ray direction
    glm::vec3 position{0.0f};
};

// Visible objects only; nothing when the ray hits no triangle.
std::optional<PickHit> pickObject(const Scene& scene, const glm::vec3& origin, const glm::vec3& direction);

// The ray through a pixel (x right, y down, in pixels of a width x height image) of `camera`.
struct Ray {
    glm::vec3 origin;
    glm::vec3 direction; // normalised
};
Ray cameraRay(const Camera& camera, float x, float y, int width, int height);

// World bounds of one object (its mesh transformed), empty if it has no mesh.
Bounds objectWorldBounds(const Scene& scene, int object);

} // namespace lpv::scene
