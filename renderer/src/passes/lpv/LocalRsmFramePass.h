#pragma once
// localRsm: spot and point lights' reflective shadow maps (LocalRsmPass.h)
// as a pass of the frame; the LPV's injection reads their faces. Its targets
// exist from its first run until a frame culls it.
#include "frame/FramePass.h"
#include "passes/lpv/LocalRsmPass.h"

#include <optional>

namespace lpv::renderer {

class LocalRsmFramePass final : public GraphPass {
  public:
    LocalRsmFramePass() : GraphPass(scene::Pass::LocalRsm) {}
    // The faces of its last run; null while it holds none.
    const LocalRsmPass* maps() const { return gpu_ && gpu_->active() ? &*gpu_ : nullptr; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override {
        if (gpu_)
            gpu_->addGpuMemory(ledger);
    }

  protected:
    // Runs while the LPV runs and the local-light analysis injects a light;
    // reused while the scene and its lights stay (the faces do not follow the camera).
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { gpu_.reset(); }

  private:
    std::optional<LocalRsmPass> gpu_;
};

} // namespace lpv::renderer
