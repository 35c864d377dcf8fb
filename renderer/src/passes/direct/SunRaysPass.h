#pragma once
// Sun rays (the thesis' "sun shafts"): an occlusion pre-pass at half
// resolution (sun disc bright, sky mid, geometry black) and a radial blur
// towards the sun's screen position, added to the HDR image before
// tonemapping. Runs only when decideSunRays says so (the sun on screen, or
// forced by effects.sunRays); otherwise it allocates nothing.
#include "frame/FramePass.h"
#include "graph/ResourceDesc.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <optional>

namespace lpv::renderer {

class SunRaysPass final : public GraphPass {
  public:
    SunRaysPass() : GraphPass(scene::Pass::SunRays) {}

    // The half-resolution occlusion image of a width x height frame (R16F, linear, clamped).
    static graph::ResourceDesc occlusionTarget(int width, int height);

  protected:
    // Runs when decideSunRays says so; reads camera.depth, adds to camera.hdr
    // through the transient sunRays.occlusion.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;
    void release() override { gpu_.reset(); }

  private:
    struct Gpu {
        Program occlusionProgram, raysProgram;
        VertexArray emptyVao;
        Framebuffer occlusionFbo, hdrFbo;
        GLuint attachedOcclusion = 0, attachedHdr = 0;
    };
    static scene::Expected<Gpu> createGpu();
    void ensureTargets(GLuint occlusion, GLuint hdrColor);
    // Adds the rays to `hdrColor` (same size as the frame) from the camera's
    // `depth`, through `occlusion` (occlusionTarget(): a transient target of the frame graph).
    void render(const FrameContext& frame, GLuint depth, GLuint hdrColor, GLuint occlusion, const scene::Light& sun);

    std::optional<Gpu> gpu_;
};

} // namespace lpv::renderer
