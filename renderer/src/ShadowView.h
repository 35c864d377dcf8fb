#pragma once
// Light-space view for the single shadow map of the forward pass.
#include "lpv/scene/Scene.h"

namespace lpv::renderer {

struct ShadowView {
    glm::mat4 viewProj{1.0f};
    float texelWorld = 0.0f; // size of one texel: per unit distance (perspective) or absolute (ortho)
    bool perspective = false;
};

// Index of the first light that casts shadows and has a 2D shadow map
// (directional or spot); -1 if none.
int findShadowLight(const scene::Scene& scene);
ShadowView makeShadowView(const scene::Light& light, const scene::Bounds& sceneBounds, int mapSize);

} // namespace lpv::renderer
