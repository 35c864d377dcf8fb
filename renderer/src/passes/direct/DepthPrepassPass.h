#pragma once
// depthPrepass (output.depthPrepass): the camera's depth of opaque and
// alpha-masked surfaces before shading, so shading lights each visible
// pixel once (forward.frag's LPV_AFTER_DEPTH_PREPASS tests it early).
#include "frame/FramePass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"

#include <memory>

namespace lpv::renderer {

class DepthPrepassPass final : public GraphPass {
  public:
    // Its programs are built now, so a shader error shows when the renderer is created.
    static scene::Expected<std::unique_ptr<DepthPrepassPass>> create();

  protected:
    // Runs when output.depthPrepass is on; writes camera.depth.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    DepthPrepassPass() : GraphPass(scene::Pass::DepthPrepass) {}
    ProgramCache programs_;
    const CachedProgram* masked_ = nullptr; // cuts alpha-masked holes
    const CachedProgram* opaque_ = nullptr; // PREPASS_OPAQUE: never discards
    // A framebuffer around the graph's camera.depth, rebuilt when it hands out another.
    Framebuffer fbo_;
    GLuint attachedDepth_ = 0;
};

} // namespace lpv::renderer
