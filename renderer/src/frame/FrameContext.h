#pragma once
// What every pass of one frame reads: the scene, the parameters, the camera
// and its matrices, the target size and the GPU timer.
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lpv::renderer {

// Hands out the texture units of one pass's bindings (the frame graph's
// PassContext::allocateUnit): every call a unit no other binding of the pass uses.
using UnitAllocator = std::function<GLuint()>;

struct FrameContext {
    const scene::Scene& scene;
    const scene::ParameterSet& params;
    const scene::Camera& camera;
    int width = 0;
    int height = 0;
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    GpuTimer& timer;
    // The scene's bounds (computed once per scene generation).
    scene::Bounds sceneBounds{};
    // The scene, the camera and every matrix above are in render space
    // (RenderSpace.h): the world moved by -anchor. A pass that draws data
    // kept in world space (a baked radiosity mesh) adds the anchor back.
    glm::dvec3 anchor{0.0};
    // How far from the world origin the scene's positions were rounded to
    // float before render space moved them (tolerances that compare them).
    float worldMagnitude() const {
        const glm::vec3 size = sceneBounds.empty() ? glm::vec3(0.0f) : sceneBounds.size();
        return float(std::max({std::abs(anchor.x), std::abs(anchor.y), std::abs(anchor.z)}) +
                     double(std::max({size.x, size.y, size.z})));
    }
};

} // namespace lpv::renderer
