#pragma once
// shadowMaps: the lights' shadow maps (ShadowPass.h) as a pass of the frame.
// Shading samples them (bindForShading); the renderer asks them for its
// counters and --dump images.
#include "frame/FramePass.h"
#include "passes/direct/ShadowPass.h"

namespace lpv::renderer {

class ShadowMapsFramePass final : public GraphPass {
  public:
    explicit ShadowMapsFramePass(ShadowPass maps)
        : GraphPass(scene::Pass::ShadowMaps), maps_(std::move(maps)) {}
    // Its programs are built now, so a shader error shows when the renderer is created.
    static scene::Expected<std::unique_ptr<ShadowMapsFramePass>> create() {
        return createAround<ShadowMapsFramePass>(ShadowPass::create());
    }

    const ShadowPass& maps() const { return maps_; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override { maps_.addGpuMemory(ledger); }

  protected:
    // Runs every frame it is read; reused while the scene, the lights, the
    // shadow parameters and (with a shadowed sun, whose cascades fit the view) the camera stay.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    ShadowPass maps_;
    // What the sun's cascade layers are drawn from this frame (ShadowPass::render's contentKey).
    std::uint64_t layersKey_ = 0;
};

} // namespace lpv::renderer
