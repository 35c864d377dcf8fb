#include "ShadowView.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

int findShadowLight(const scene::Scene& scene) {
    for (std::size_t i = 0; i < scene.lights.size() && i < 8; ++i) {
        const scene::Light& l = scene.lights[i];
        if (l.castShadows && l.type != scene::LightType::Point)
            return int(i);
    }
    return -1;
}

namespace {

glm::vec3 stableUp(const glm::vec3& dir) {
    return std::abs(dir.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

ShadowView makeShadowView(const scene::Light& light, const scene::Bounds& bounds, int mapSize) {
    ShadowView v;
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.size()), 1e-3f);
    if (light.type == scene::LightType::Spot) {
        // Cover the cone, clamped below 180 degrees where a perspective projection degenerates.
        const float fov = std::min(2.0f * light.outerConeAngle, glm::radians(170.0f));
        const float far = glm::length(light.position - center) + radius;
        const float near = std::max(far * 1e-3f, 1e-3f);
        const glm::mat4 view = glm::lookAt(light.position, light.position + dir, stableUp(dir));
        v.viewProj = glm::perspective(fov, 1.0f, near, far) * view;
        v.texelWorld = 2.0f * std::tan(0.5f * fov) / float(mapSize);
        v.perspective = true;
    } else {
        // Orthographic box around the whole scene (issue #4 replaces this with cascades).
        const glm::mat4 view = glm::lookAt(center - dir * radius * 2.0f, center, stableUp(dir));
        v.viewProj = glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) * view;
        v.texelWorld = 2.0f * radius / float(mapSize);
        v.perspective = false;
    }
    return v;
}

} // namespace lpv::renderer
