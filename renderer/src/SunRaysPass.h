#pragma once
// Sun rays (the thesis' "sun shafts"): an occlusion pre-pass at half
// resolution (sun disc bright, sky mid, geometry black) and a radial blur
// towards the sun's screen position, added to the HDR image before
// tonemapping. Runs only when decideSunRays says so (the sun on screen, or
// forced by effects.sunRays); otherwise it allocates nothing.
#include "FrameContext.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneAnalysis.h"

namespace lpv::renderer {

using scene::Expected;

class SunRaysPass {
public:
    static Expected<SunRaysPass> create();

    // Adds the rays to `hdrColor` (same size as the frame) from the camera's `depth`.
    void render(const FrameContext& frame, GLuint depth, GLuint hdrColor, const scene::Light& sun);

private:
    SunRaysPass() = default;
    void ensureTargets(int width, int height, GLuint hdrColor);

    Program occlusionProgram_, raysProgram_;
    VertexArray emptyVao_;
    Texture occlusion_;
    Framebuffer occlusionFbo_, hdrFbo_;
    int width_ = 0, height_ = 0;
    GLuint attachedHdr_ = 0;
};

} // namespace lpv::renderer
