#include "RenderSpace.h"

#include <cmath>

namespace lpv::renderer {

glm::dvec3 renderAnchor(const scene::Bounds& worldBounds) {
    if (worldBounds.empty())
        return glm::dvec3(0.0);
    const glm::dvec3 corner = glm::dvec3(worldBounds.min);
    const bool finite = std::isfinite(corner.x) && std::isfinite(corner.y) && std::isfinite(corner.z);
    return finite ? corner : glm::dvec3(0.0);
}

void RenderSpace::setScene(const scene::Scene& world) { scene_.meshes = world.meshes; }

const scene::Scene& RenderSpace::update(const scene::Scene& world, const scene::Bounds& worldBounds) {
    anchor_ = renderAnchor(worldBounds);
    scene_.materials = world.materials;
    scene_.objects = world.objects;
    scene_.lights = world.lights;
    scene_.cameras.clear(); // the frame's camera comes separately (toRender)
    scene_.cameraPaths.clear();
    scene_.sky = world.sky;
    for (scene::Object& o : scene_.objects)
        if (o.parent < 0 || std::size_t(o.parent) >= scene_.objects.size())
            o.transform.translation = toRender(o.transform.translation);
    for (scene::Light& l : scene_.lights)
        l.position = toRender(l.position);
    return scene_;
}

scene::Camera RenderSpace::toRender(const scene::Camera& world) const {
    scene::Camera c = world;
    c.position = toRender(world.position);
    c.target = toRender(world.target);
    return c;
}

} // namespace lpv::renderer
