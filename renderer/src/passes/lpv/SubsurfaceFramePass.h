#pragma once
// subsurface: the subsurface LPV (LpvSubsurfacePass.h) as a pass of the
// frame, fed by the sun's RSM (its translucent texels) after the LPV's
// injection. Its volume exists from its first run until a frame culls it.
#include "frame/FramePass.h"
#include "passes/lpv/LpvSubsurfacePass.h"

#include <optional>

namespace lpv::renderer {

class SubsurfaceFramePass final : public GraphPass {
  public:
    SubsurfaceFramePass() : GraphPass(scene::Pass::Subsurface) {}
    // What shading samples; null while the pass holds no volume.
    const LpvSubsurfacePass* volume() const { return gpu_ ? &*gpu_ : nullptr; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { gpu_.reset(); }

  private:
    std::optional<LpvSubsurfacePass> gpu_;
};

} // namespace lpv::renderer
