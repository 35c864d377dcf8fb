#pragma once
// Render space (issue #41): the renderer draws the scene moved so that the
// corner of its bounds lies at the origin. Positions reach the GPU (and the
// LPV's cells, the RSM and shadow windows, the scene's geometry volume)
// relative to the scene, computed in double on the CPU, so
// - a scene 100 km or 1,000 km from the world origin renders as it does at
//   the origin: float positions near 1e5 have 8 mm steps, near 1e6 6 cm;
// - the LPV's cells line up with the scene's bounds wherever the scene
//   lies, so moving a scene does not move its walls inside the cells (the
//   Cornell box's indirect light varied from 0.55x to 0.77x of the
//   reference with the cells' phase against its walls, docs/lpv.md).
// Objects' meshes stay in their own space; only root objects' translations,
// lights' and the camera's positions move. Everything the renderer hands
// back in world space (cascade frames, LPV snapshots) is moved back.
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace lpv::renderer {

class RenderSpace {
public:
    // A new scene (its meshes are copied once: they do not move).
    void setScene(const scene::Scene& world);
    // `world` moved into render space. Objects, materials and the anchor
    // (from `worldBounds`) are taken when `generation` changes (every scene
    // edit bumps it); lights and sky every call (they change without one),
    // so a frame copies only a handful of lights.
    const scene::Scene& update(const scene::Scene& world, const scene::Bounds& worldBounds,
                               std::uint64_t generation);
    const scene::Scene& scene() const { return scene_; }

    // The world position of render space's origin.
    const glm::dvec3& anchor() const { return anchor_; }
    glm::vec3 toRender(const glm::vec3& world) const { return glm::vec3(glm::dvec3(world) - anchor_); }
    glm::vec3 toWorld(const glm::vec3& render) const { return glm::vec3(glm::dvec3(render) + anchor_); }
    scene::Camera toRender(const scene::Camera& world) const;

private:
    scene::Scene scene_;
    glm::dvec3 anchor_{0.0};
    std::uint64_t generation_ = ~std::uint64_t(0);
};

// The anchor of a scene: the minimum corner of its world bounds (the origin
// for an empty scene).
glm::dvec3 renderAnchor(const scene::Bounds& worldBounds);

} // namespace lpv::renderer
