#pragma once
// skyHeight: sky injection's top-down depth map (SkyHeightPass.h) as a pass
// of the frame. The map and its placement (LpvSkyInput) stay with the pass
// from its first run until a frame culls it; the sky injection stage reads
// them (LpvStageInputs::skyInput).
#include "frame/FramePass.h"
#include "passes/lpv/SkyHeightPass.h"

#include <optional>

namespace lpv::renderer {

class SkyHeightFramePass final : public GraphPass {
  public:
    SkyHeightFramePass() : GraphPass(scene::Pass::SkyHeight) {}
    // The height map this pass last rendered; null while it holds none.
    const LpvSkyInput* input() const { return input_ ? &*input_ : nullptr; }

  protected:
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override {
        gpu_.reset();
        input_.reset();
    }

  private:
    std::optional<SkyHeightPass> gpu_;
    std::optional<LpvSkyInput> input_;
};

} // namespace lpv::renderer
