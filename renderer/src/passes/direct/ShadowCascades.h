#pragma once
// Cascaded shadow maps for the sun, as plain math (no GL): where the camera
// frustum is split, the bounding sphere of each split, and each cascade's
// orthographic light view-projection, optionally snapped to its texel grid.
#include "lpv/scene/Mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::renderer {

// Weight of the logarithmic split in the practical split scheme (Zhang et
// al. 2006): split_i = lambda * log_i + (1 - lambda) * uniform_i. 0.75 keeps
// the near cascades dense (log) without starving the far ones (uniform);
// the far distance is clamped to the scene, so the far cascades stay useful.
inline constexpr float kCascadeSplitLambda = 0.75f;

// count + 1 view distances from `near` to `far`, strictly increasing.
std::vector<float> cascadeSplits(int count, float near, float far, float lambda = kCascadeSplitLambda);

// The camera the cascades cover.
struct CascadeCamera {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit view direction
    float fovY = 0.785398f;               // radians
    float aspect = 1.0f;
    float nearPlane = 0.05f;
    float farPlane = 500.0f;
};

struct CascadeSettings {
    int count = 6;
    int mapSize = 1024;
    bool stabilize = true;
    float lambda = kCascadeSplitLambda;
};

struct ShadowCascade {
    glm::mat4 viewProj{1.0f};
    float splitNear = 0.0f; // view distance this cascade starts at
    float splitFar = 0.0f;  // ... and ends at
    glm::vec3 center{0.0f}; // bounding sphere of the split (world), before snapping
    float radius = 0.0f;       // half the cascade's width (the sphere's radius, rounded up when stabilised)
    float sphereRadius = 0.0f; // the sphere's own radius, before rounding
    glm::vec2 lightCenter{0.0f}; // centre of the cascade in light space (snapped when stabilised)
    float depthNear = 0.0f;      // light-space depth range (distances along the light)
    float depthFar = 0.0f;
    float texelWorld = 0.0f; // world size of one shadow texel
    float depthRange = 0.0f; // world distance along the light from depth 0 to depth 1
};

// Light view (a rotation: looks along `lightDir` from the origin) shared by all cascades.
glm::mat4 lightRotation(const glm::vec3& lightDir);

// Far distance of the cascades: the camera's far plane, clamped to the
// farthest corner of the scene (a distance, so camera rotation does not change it).
float cascadeFarDistance(const CascadeCamera& camera, const scene::Bounds& sceneBounds);

// One cascade per split. Each covers the bounding sphere of its frustum slice
// (its size does not depend on the camera's rotation) and, along the light,
// the whole scene, so that casters outside the camera frustum still cast.
std::vector<ShadowCascade> buildCascades(const CascadeCamera& camera, const glm::vec3& lightDir,
                                         const scene::Bounds& sceneBounds, const CascadeSettings& settings);

// Whether the cascade `drawn` (an earlier frame's, same light and map) still
// covers the whole slice that `wanted` was fitted to: the slice's bounding
// sphere lies inside `drawn`'s square in light space. Along the light both
// cover the whole scene.
bool cascadeCovers(const ShadowCascade& drawn, const ShadowCascade& wanted, const glm::vec3& lightDir);

// A light-space box (as a view-projection) containing every cascade: cull
// shadow casters against it once for all cascades.
glm::mat4 cascadeUnionViewProj(const std::vector<ShadowCascade>& cascades, const glm::vec3& lightDir,
                               const scene::Bounds& sceneBounds);

} // namespace lpv::renderer
