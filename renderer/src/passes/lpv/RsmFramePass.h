#pragma once
// rsm: the sun's reflective shadow maps (RsmPass.h) as a pass of the frame,
// one tile per cascade of rsm.cascades (the LPV's placement). The LPV's
// injection and geometry volume and the subsurface LPV read its tiles.
#include "frame/FramePass.h"
#include "passes/lpv/RsmPass.h"

#include <memory>

namespace lpv::renderer {

class RsmFramePass final : public GraphPass {
  public:
    explicit RsmFramePass(RsmPass rsm) : GraphPass(scene::Pass::Rsm), rsm_(std::move(rsm)) {}
    // Built with the renderer, so a shader error shows when it is created.
    static scene::Expected<std::unique_ptr<RsmFramePass>> create() {
        return createAround<RsmFramePass>(RsmPass::create());
    }

    const RsmPass& maps() const { return rsm_; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    // Runs while the LPV runs and the sun lights the scene; reused while the
    // scene, the lights and the tiles' placement (which follows the camera's position) stay.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { rsm_.release(); }

  private:
    RsmPass rsm_;
};

} // namespace lpv::renderer
