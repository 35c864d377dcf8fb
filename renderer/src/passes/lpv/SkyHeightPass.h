#pragma once
// Sky light injection's top-down view (docs/lpv.md): the scene's depth seen
// straight from above, over the x-z extent of the coarsest LPV cascade, so
// the LPV knows per column where the highest surface is and where open sky
// begins. Allocated on first use; ForwardRenderer drops the pass when sky
// injection does not run.
#include "frame/FrameContext.h"
#include "passes/lpv/LpvPass.h"
#include "scenegpu/MaterialGpu.h"
#include "passes/lpv/RsmCascades.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

namespace lpv::renderer {

// How far the map's top and bottom stand beyond the scene: 1% of its height,
// or of a thousandth of its width for a flat scene (issue #41: no 1 m floor,
// which put the planes of a 2 cm scene 50% of its size away).
float skyHeightMargin(const scene::Bounds& bounds);

class SkyHeightPass {
  public:
    static scene::Expected<SkyHeightPass> create();

    // Renders the depth map at `resolution`^2 texels over
    // `coarsest`'s x-z extent, from above the scene down to below it. The
    // result's radiance is left zero for the caller.
    scene::Expected<LpvSkyInput> render(const FrameContext& frame, const SceneGpu& geometry,
                                        const MaterialGpu& materials, const LpvCascade& coarsest, int resolution);

    // The resolution that gives two texels per finest cell: gridSize * 2^(cascades-1) * 2, at most 2048.
    static int resolutionFor(int gridSize, int cascades);

  private:
    SkyHeightPass() = default;
    Program program_;
    Texture depth_;
    Framebuffer fbo_;
    int size_ = 0;
};

} // namespace lpv::renderer
