#pragma once
// Which lights get shadow maps, and the light-space views of spot and point
// lights (the sun's cascades are in ShadowCascades.h). Plain math, no GL.
#include "lpv/scene/Scene.h"

#include <array>
#include <vector>

namespace lpv::renderer {

// Shading reads at most this many lights (common.glsl MAX_LIGHTS).
inline constexpr int kMaxShadedLights = 8;
// At most this many point and spot lights together get a shadow map; each
// costs a full scene pass (six cube faces for a point light), so the first
// four shadow-casting local lights in scene order get them, the rest are unshadowed.
inline constexpr int kMaxShadowedLocalLights = 4;

struct ShadowLightSelection {
    int sun = -1;            // first shadow-casting directional light, -1 = none
    std::vector<int> spots;  // light indices, in scene order
    std::vector<int> points; // light indices, in scene order
};

ShadowLightSelection selectShadowLights(const scene::Scene& scene);

// A spot or point map's near plane as a fraction of its far plane (the
// distance to the farthest scene corner): scene-relative, so a 2 cm and a
// 2 km scene get the same depth layout. shadow_sampling.glsl's blocker floor
// is the same fraction.
inline constexpr float kLocalShadowNearFraction = 1e-3f;

// Perspective view of one local light: 1 face for a spot, 6 cube faces for a
// point light (in GL cube-map face order +X, -X, +Y, -Y, +Z, -Z). The map
// stores distance to the light divided by `far`.
struct LocalShadowView {
    std::array<glm::mat4, 6> viewProj{};
    int faces = 1;
    float nearPlane = 0.01f;
    float farPlane = 1.0f;
    float tanHalfFov = 1.0f; // of one face
};

// An area light casts its shadows from this many cube maps, one at the
// centre of each quarter of its rectangle (a disc: of its bounding square).
// One cube at the centre of a lamp a quarter as wide as the Cornell box
// cannot say which part of the lamp a receiver sees past a blocker (issue
// #46): its estimate erred most beside vertical faces and on faces that see
// only part of the lamp. A quarter's penumbrae are half as wide, and the
// four together tile the lamp's, so their sum stays smooth.
inline constexpr int kAreaShadowCubes = 4;
std::array<glm::vec3, kAreaShadowCubes> areaShadowCentres(const scene::Light& light);
// Cubes of the point-light map at most: every shadowed local light an area light.
inline constexpr int kMaxPointShadowCubes = kMaxShadowedLocalLights * kAreaShadowCubes;

LocalShadowView spotShadowView(const scene::Light& light, const scene::Bounds& sceneBounds);
LocalShadowView pointShadowView(const scene::Light& light, const scene::Bounds& sceneBounds);

} // namespace lpv::renderer
