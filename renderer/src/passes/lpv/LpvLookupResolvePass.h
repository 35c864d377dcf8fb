#pragma once
// lpvLookupResolve (issue #48 item 1): the LPV's diffuse lookup at 1/2 or 1/4
// of the view's resolution (the lpvLookup pass) brought to every pixel, so
// that shading reads one texel in place of a lookup. It draws the opaque and
// masked surfaces at full resolution over the camera's depth (the pre-pass's,
// or its own when output.depthPrepass is off) and upsamples the low-resolution
// image with depth- and normal-aware weights (lpv_lookup_upsample.glsl) into
// lpv.resolved (RGBA16F, rgb the irradiance). The pixels whose low-resolution
// neighbours all lie on other surfaces go on a list that a compute pass looks
// up at full resolution (lpv_lookup_fallback.comp): on llvmpipe a fragment
// shader runs a branch's lookup under an execution mask at every pixel, taken
// or not, so the lookup must not be compiled into any full-screen shader.
// It declares lpv.resolved as the frame's indirect light
// (IndirectLight::Lookup::LpvReducedResolution): shading's opaque and masked
// draws read it (forward.frag's LPV_LOOKUP_RESOLVED), blended ones (glass
// over the surface seen here) look the LPV up themselves.
#include "frame/FramePass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"

#include <array>
#include <cstddef>
#include <string_view>

namespace lpv::renderer {

class LpvLookupResolvePass final : public GraphPass {
  public:
    static constexpr std::string_view kName = "lpvLookupResolve";
    // The irradiance at each pixel's opaque or masked surface (RGBA16F, rgb),
    // and the depth it was drawn with when there is no pre-pass (else camera.depth).
    static constexpr graph::ResourceHandle Resolved{"lpv.resolved"};
    static constexpr graph::ResourceHandle ResolveDepth{"lpv.resolveDepth"};
    static constexpr std::array kOutputs{Resolved, ResolveDepth};

    LpvLookupResolvePass() : GraphPass(kName) {}
    void addGpuMemory(GpuMemoryLedger& ledger) const override;

  protected:
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override {
        fbo_ = {};
        attached_ = {};
        list_ = {};
        listEntries_ = 0;
    }

  private:
    // The fallback list for a view of `pixels` pixels.
    void reserveList(std::size_t pixels);

    ProgramCache programs_;
    Framebuffer fbo_;
    std::array<GLuint, 2> attached_{};
    Buffer list_;
    std::size_t listEntries_ = 0;
    bool ownDepth_ = false;   // output.depthPrepass is off: the pass draws its own depth first
    bool visibility_ = false; // this frame's LPV has its visibility moments bound
    int reduction_ = 1;       // this frame's LpvLookupPass::resolution()
};

} // namespace lpv::renderer
