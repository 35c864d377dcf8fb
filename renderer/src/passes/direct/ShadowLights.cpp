#include "passes/direct/ShadowLights.h"

#include "lpv/scene/AreaLight.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

ShadowLightSelection selectShadowLights(const scene::Scene& scene) {
    ShadowLightSelection s;
    int local = 0;
    for (int i = 0; i < int(scene.lights.size()) && i < kMaxShadedLights; ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        if (!l.castShadows)
            continue;
        if (l.type == scene::LightType::Directional) {
            if (s.sun < 0)
                s.sun = i;
        } else if (local < kMaxShadowedLocalLights) {
            // An area light casts its shadows from a cube map at its centre, softened by its size.
            (l.type == scene::LightType::Spot ? s.spots : s.points).push_back(i);
            ++local;
        }
    }
    return s;
}

namespace {

// Distance from the light to the farthest scene corner (or its range, if
// shorter). Scene-relative: no metre floor (which made a 2 cm scene's map 1 m
// deep); 1 remains only for a light with no scene and no range around it.
float farDistance(const scene::Light& light, const scene::Bounds& b) {
    float far = 0.0f;
    if (!b.empty())
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                              corner & 4 ? b.max.z : b.min.z};
            far = std::max(far, glm::length(p - light.position));
        }
    if (light.range > 0.0f)
        far = far > 0.0f ? std::min(far, light.range) : light.range;
    if (!(far > 0.0f) || !std::isfinite(far))
        far = 1.0f;
    return far * 1.01f;
}

glm::vec3 stableUp(const glm::vec3& dir) {
    return std::abs(dir.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

std::array<glm::vec3, kAreaShadowCubes> areaShadowCentres(const scene::Light& light) {
    const scene::AreaLightFrame f = scene::areaLightFrame(light);
    // Quarters in the order shadow_sampling.glsl numbers them: bit 0 = +U half, bit 1 = +V half.
    std::array<glm::vec3, kAreaShadowCubes> centres{};
    for (int k = 0; k < kAreaShadowCubes; ++k)
        centres[std::size_t(k)] =
            f.center + 0.5f * ((k & 1) ? f.halfU : -f.halfU) + 0.5f * ((k & 2) ? f.halfV : -f.halfV);
    return centres;
}

LocalShadowView spotShadowView(const scene::Light& light, const scene::Bounds& bounds) {
    LocalShadowView v;
    v.faces = 1;
    v.farPlane = farDistance(light, bounds);
    v.nearPlane = v.farPlane * kLocalShadowNearFraction;
    // Cover the cone, clamped below 180 degrees where a perspective projection degenerates.
    const float fov = std::min(2.0f * light.outerConeAngle, glm::radians(170.0f));
    v.tanHalfFov = std::tan(0.5f * fov);
    const glm::vec3 dir = glm::normalize(light.direction);
    v.viewProj[0] = glm::perspective(fov, 1.0f, v.nearPlane, v.farPlane) *
                    glm::lookAt(light.position, light.position + dir, stableUp(dir));
    return v;
}

LocalShadowView pointShadowView(const scene::Light& light, const scene::Bounds& bounds) {
    LocalShadowView v;
    v.faces = 6;
    v.farPlane = farDistance(light, bounds);
    v.nearPlane = v.farPlane * kLocalShadowNearFraction;
    v.tanHalfFov = 1.0f;
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, v.nearPlane, v.farPlane);
    // The GL cube-map face conventions (the face's "up" is -t of the spec's table).
    const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    for (int f = 0; f < 6; ++f)
        v.viewProj[std::size_t(f)] = projection * glm::lookAt(light.position, light.position + dirs[f], ups[f]);
    return v;
}

} // namespace lpv::renderer
