#pragma once
// lpvLookup (issue #48 item 1): the LPV's diffuse lookup (lpv_lookup.glsl's
// lpvIrradiance, with its cascade blend, damping and visibility weights) at
// 1/2 or 1/4 of the view's resolution, lpv.lookupResolution = half|quarter.
// It draws the opaque and masked surfaces from the camera into its own small
// targets: lpv.lookup (RGBA16F: rgb the irradiance, a the distance from the
// camera over its far plane) and lpv.lookupNormal (the interpolated vertex
// normal, turned toward the viewer). The lpvLookupResolve pass
// (LpvLookupResolvePass.h) upsamples it with depth- and normal-aware weights
// over the 2x2 low-resolution neighbours (lpv_lookup_upsample.glsl) into an
// image of the view that shading reads, and looks up at full resolution
// where none of them lies on its surface. At full resolution it does not run.
#include "frame/FramePass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"

#include <array>

namespace lpv::renderer {

class LpvLookupPass final : public GraphPass {
  public:
    LpvLookupPass() : GraphPass(scene::Pass::LpvLookup) {}

    // lpv.lookupResolution for this frame (SceneAnalysis.h's
    // decideLookupResolution: auto decides from the view and the scene): the
    // number of full-resolution pixels along one low-resolution texel (1, 2 or 4), and why.
    static LookupResolutionDecision resolution(const FrameState& state);

  protected:
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { fbo_ = {}; attached_ = {}; }

  private:
    ProgramCache programs_;
    Framebuffer fbo_;
    std::array<GLuint, 3> attached_{};
    bool visibility_ = false; // this frame's LPV has its visibility moments bound
    int reduction_ = 1;       // this frame's resolution()
};

} // namespace lpv::renderer
