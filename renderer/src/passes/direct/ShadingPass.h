#pragma once
// shading: the forward pass (forward.vert, forward.frag) that lights every
// visible surface with the direct light (the shadow maps of FrameState), adds the indirect
// light the frame's passes declared (IndirectLight.h) and writes the camera
// G-buffer (normal, albedo, depth) beside the HDR image.
#include "frame/FramePass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace lpv::renderer {

class ShadingPass final : public GraphPass {
  public:
    // Builds forward.frag with every feature (with and without the depth
    // pre-pass) now, so a renderer that exists can shade; frames use the
    // variant with only what they need.
    static scene::Expected<std::unique_ptr<ShadingPass>> create();

    // forward.frag has the subsurface LPV's sampler (GL gives enough fragment texture units).
    bool hasSubsurfaceSampler() const { return subsurfaceSampler_; }
    // The visualizers' view of the sun's shadow cascades.
    void setShadowCascadeTint(bool on) { cascadeTint_ = on; }
    // What the last frame drew from the camera.
    const DrawListStats& cameraStats() const { return stats_; }
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    // Runs every frame (the image). Reads the shadow maps, the pre-pass's
    // depth and every indirect light declared before it; decides glossy reflections.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    ShadingPass() : GraphPass(scene::Pass::Shading) {}
    // The variant of forward.frag this frame needs (on llvmpipe code that is
    // compiled in but not taken still slows every pixel: docs/renderer.md).
    const CachedProgram& variant(const FrameState& state, const std::vector<std::string>& indirectDefines);
    void attach(graph::PassContext& ctx);

    ProgramCache programs_;
    std::array<const CachedProgram*, 2> full_{}; // [afterPrepass]
    std::vector<std::string> defines_;           // what every variant defines (the subsurface sampler's absence)
    bool subsurfaceSampler_ = true;
    // The GGX LTC table for area lights' specular lobe (scene/LtcSpecular.h), uploaded once.
    Buffer ltcTable_;
    bool glossyRuns_ = false; // this frame's glossy reflections decision
    bool cascadeTint_ = false;
    DrawListStats stats_;
    // A framebuffer around the graph's camera targets, rebuilt when it hands out others.
    Framebuffer fbo_;
    std::array<GLuint, 4> attached_{};
};

} // namespace lpv::renderer
