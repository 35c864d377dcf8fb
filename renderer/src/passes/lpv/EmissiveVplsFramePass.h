#pragma once
// emissiveVpls: emissive surfaces sampled into VPLs on the CPU
// (lpvref::sampleEmissiveVpls) and uploaded (EmissiveVplBuffer.h) as a pass
// of the frame, once per scene; the LPV's injection reads them.
#include "frame/FramePass.h"
#include "passes/lpv/EmissiveVplBuffer.h"

#include <optional>

namespace lpv::renderer {

class EmissiveVplsFramePass final : public GraphPass {
  public:
    EmissiveVplsFramePass() : GraphPass(scene::Pass::EmissiveVpls) {}
    // The VPLs of its last run; null while it holds none.
    const EmissiveVplBuffer* vpls() const { return vpls_ && !vpls_->empty() ? &*vpls_ : nullptr; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    // Runs while the LPV runs and an emissive surface is not an area light's own; reused while the scene stays.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { vpls_.reset(); }

  private:
    std::optional<EmissiveVplBuffer> vpls_;
};

} // namespace lpv::renderer
