#include "passes/direct/DepthPrepassPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"

#include <glm/gtc/type_ptr.hpp>

namespace lpv::renderer {

scene::Expected<std::unique_ptr<DepthPrepassPass>> DepthPrepassPass::create() {
    std::unique_ptr<DepthPrepassPass> pass(new DepthPrepassPass());
    auto masked = pass->programs_.get({{"forward.vert", "depth_prepass.frag"}, {}});
    if (!masked)
        return std::unexpected(masked.error());
    auto opaque = pass->programs_.get({{"forward.vert", "depth_prepass.frag"}, {"PREPASS_OPAQUE 1"}});
    if (!opaque)
        return std::unexpected(opaque.error());
    pass->masked_ = *masked;
    pass->opaque_ = *opaque;
    return pass;
}

void DepthPrepassPass::setup(graph::PassSpec& pass, FrameState& state) {
    pass.decision = state.depthPrepass ? runsBecause("output.depthPrepass is on: shading lights each visible pixel once")
                                       : skippedBecause("output.depthPrepass is off");
    pass.writes = {resources::CameraDepth};
}

scene::Expected<void> DepthPrepassPass::execute(graph::PassContext& ctx, FrameState& state) {
    const FrameContext& frame = ctx.frame;
    const GLuint depth = ctx.id(resources::CameraDepth);
    if (depth != attachedDepth_) {
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth, 0);
        glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        attachedDepth_ = depth;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Opaque and masked surfaces only: blended ones neither hide nor write
    // depth. Opaque ones through the program that never discards, so their
    // depth is tested early (on llvmpipe a discard defers it).
    const SurfaceDraws draws = surfaceDraws(state.sceneGpu->draws(), frame.viewProj, frame.camera.position);
    const auto& opaque = draws.opaque;
    const auto& masked = draws.masked;
    for (const auto& [shader, list] : {std::pair{opaque_, &opaque}, std::pair{masked_, &masked}}) {
        if (list->empty())
            continue;
        const GLuint program = shader->id();
        glUseProgram(program);
        glProgramUniformMatrix4fv(program, shader->uniform("uViewProj"), 1, GL_FALSE,
                                  glm::value_ptr(frame.viewProj));
        state.sceneGpu->draw(program, *list, [&](std::uint32_t m) {
            state.materialGpu->bind(program, m, MaterialBindMode::Coverage);
        });
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return {};
}

} // namespace lpv::renderer
