#include "scenegpu/RenderSpace.h"

#include "lpv/scene/SceneScale.h"

#include <cmath>

namespace lpv::renderer {

glm::dvec3 renderAnchor(const scene::Bounds& worldBounds) {
    if (worldBounds.empty())
        return glm::dvec3(0.0);
    const glm::dvec3 corner = glm::dvec3(worldBounds.min);
    const bool finite = std::isfinite(corner.x) && std::isfinite(corner.y) && std::isfinite(corner.z);
    return finite ? corner : glm::dvec3(0.0);
}

void RenderSpace::setScene(const scene::Scene& world) {
    scene_.meshes = world.meshes;
    generation_ = ~std::uint64_t(0);
}

const scene::Scene& RenderSpace::update(const scene::Scene& world, const scene::Bounds& worldBounds,
                                        std::uint64_t generation) {
    if (generation != generation_) {
        generation_ = generation;
        anchor_ = renderAnchor(worldBounds);
        scene_.materials = world.materials;
        scene_.objects = world.objects;
        scene_.lights.clear();
        scene_.cameras.clear(); // the frame's camera comes separately (toRender)
        scene_.cameraPaths.clear();
        scene::moveScene(scene_, -anchor_);
    }
    scene_.lights = world.lights;
    for (scene::Light& l : scene_.lights)
        l.position = toRender(l.position);
    scene_.sky = world.sky;
    return scene_;
}

scene::Camera RenderSpace::toRender(const scene::Camera& world) const {
    scene::Camera c = world;
    c.position = toRender(world.position);
    c.target = toRender(world.target);
    return c;
}

} // namespace lpv::renderer
