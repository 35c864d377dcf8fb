#pragma once
// exposure (output.exposureMode = auto): the HDR image metered on the GPU
// (AutoExposurePass.h) into the buffer tonemap reads, adapting over time
// when the renderer is given a time step (the editor), at once otherwise.
#include "frame/FramePass.h"
#include "passes/direct/AutoExposurePass.h"

#include <memory>
#include <optional>

namespace lpv::renderer {

class ExposureFramePass final : public GraphPass {
  public:
    explicit ExposureFramePass(AutoExposurePass meter)
        : GraphPass(scene::Pass::Exposure), meter_(std::move(meter)) {}
    // Its programs and buffers are made now: the buffer outlives manual frames.
    static scene::Expected<std::unique_ptr<ExposureFramePass>> create() {
        return createAround<ExposureFramePass>(AutoExposurePass::create());
    }

    AutoExposurePass& meter() { return meter_; }
    const AutoExposurePass& meter() const { return meter_; }
    // Seconds since the last frame, for the adaptation (nullopt: each frame metered on its own).
    void setTimeStep(std::optional<double> seconds) { timeStep_ = seconds; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override { meter_.addGpuMemory(ledger); }

  protected:
    // Runs when output.exposureMode is auto; reads camera.hdr, writes exposure.
    // Under manual it forgets the adapted exposure: back on auto, it starts from its target.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    AutoExposurePass meter_;
    std::optional<double> timeStep_;
};

} // namespace lpv::renderer
