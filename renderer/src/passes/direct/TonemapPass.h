#pragma once
// tonemap: the HDR image to the display image (tonemap.frag): exposure
// (manual, or the metered one from the exposure pass), the operator of
// output.tonemapper, sRGB encoding.
#include "frame/FramePass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"

#include <memory>

namespace lpv::renderer {

class TonemapPass final : public GraphPass {
  public:
    // Its program is built now, so a shader error shows when the renderer is created.
    static scene::Expected<std::unique_ptr<TonemapPass>> create();
    // The framebuffer around the last frame's display image (0 before the first frame).
    GLuint framebuffer() const { return fbo_.id(); }

  protected:
    // Runs every frame (it draws the image); reads camera.hdr and, under auto exposure, exposure.
    void setup(graph::PassSpec& pass, FrameState& state) override;
    scene::Expected<void> execute(graph::PassContext& ctx, FrameState& state) override;

  private:
    TonemapPass() : GraphPass(scene::Pass::Tonemap) {}
    ProgramCache programs_;
    const CachedProgram* program_ = nullptr;
    VertexArray emptyVao_;
    bool autoExposure_ = false;
    // Rebuilt when the graph hands out another display target.
    Framebuffer fbo_;
    GLuint attachedDisplay_ = 0;
};

} // namespace lpv::renderer
