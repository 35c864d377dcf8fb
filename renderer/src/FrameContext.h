#pragma once
// What every pass of one frame reads: the scene, the parameters, the camera
// and its matrices, the target size and the GPU timer.
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

namespace lpv::renderer {

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
};

} // namespace lpv::renderer
