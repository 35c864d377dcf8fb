#pragma once
// Reflective shadow maps (Dachsbacher & Stamminger 2005): per texel the world
// position, normal and reflected flux of what the sun sees, one tile per LPV
// cascade. The LPV injection reads them as virtual point lights.
#include "FrameContext.h"
#include "MaterialGpu.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

namespace lpv::renderer {

class RsmPass {
public:
    static scene::Expected<RsmPass> create();

    // Renders every tile of this frame (timed as "rsm"); nothing without a sun.
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry, const MaterialGpu& materials);

    // Position, normal and flux of every tile of the last frame.
    std::vector<DebugImage> debugImages() const;

private:
    RsmPass() = default;
};

} // namespace lpv::renderer
