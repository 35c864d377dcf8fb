#pragma once
// Sun rays (the thesis' "sun shafts"): an occlusion pre-pass at half
// resolution (sun disc bright, sky mid, geometry black) and a radial blur
// towards the sun's screen position, added to the HDR image before
// tonemapping. Runs only when decideSunRays says so (the sun on screen, or
// forced by effects.sunRays); otherwise it allocates nothing.
#include "frame/FrameContext.h"
#include "graph/ResourceDesc.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneAnalysis.h"

namespace lpv::renderer {

using scene::Expected;

class SunRaysPass {
public:
    static Expected<SunRaysPass> create();

    // Adds the rays to `hdrColor` (same size as the frame) from the camera's
    // `depth`, through `occlusion` (occlusionTarget(): a transient target of the frame graph).
    void render(const FrameContext& frame, GLuint depth, GLuint hdrColor, GLuint occlusion, const scene::Light& sun);
    // The half-resolution occlusion image of a width x height frame (R16F, linear, clamped).
    static graph::ResourceDesc occlusionTarget(int width, int height);

private:
    SunRaysPass() = default;
    void ensureTargets(GLuint occlusion, GLuint hdrColor);

    Program occlusionProgram_, raysProgram_;
    VertexArray emptyVao_;
    Framebuffer occlusionFbo_, hdrFbo_;
    GLuint attachedOcclusion_ = 0, attachedHdr_ = 0;
};

} // namespace lpv::renderer
