#include "passes/direct/TonemapPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"

#include <cmath>
#include <stdexcept>

namespace lpv::renderer {
namespace {

// output.tonemapper as tonemap.frag's uOperator: the shader's numbering
// follows the registry's order. A value the registry does not list is a
// programming error, not a default.
int tonemapperIndex(const scene::ParameterSet& params) {
    const std::string value = params.getEnum("output.tonemapper");
    int i = 0;
    for (const char* name : {"aces", "reinhard", "uncharted2", "linear", "neutral"}) {
        if (value == name)
            return i;
        ++i;
    }
    throw std::logic_error("output.tonemapper = '" + value + "' has no shader index");
}

} // namespace

scene::Expected<std::unique_ptr<TonemapPass>> TonemapPass::create() {
    std::unique_ptr<TonemapPass> pass(new TonemapPass());
    auto program = pass->programs_.get({{"fullscreen.vert", "tonemap.frag"}, {}});
    if (!program)
        return std::unexpected(program.error());
    pass->program_ = *program;
    pass->emptyVao_ = createVertexArray();
    return pass;
}

void TonemapPass::setup(graph::PassSpec& pass, FrameState& state) {
    autoExposure_ = state.frame.params.getEnum("output.exposureMode") == "auto";
    pass.decision = runsBecause("the display image");
    pass.final = true;
    pass.reads = {resources::CameraHdr};
    if (autoExposure_)
        pass.reads.push_back(resources::Exposure);
    pass.writes = {resources::Display};
}

scene::Expected<void> TonemapPass::execute(graph::PassContext& ctx, FrameState&) {
    const FrameContext& frame = ctx.frame;
    const GLuint display = ctx.id(resources::Display);
    if (display != attachedDisplay_) {
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, display, 0);
        attachedDisplay_ = display;
    }
    const CachedProgram& shader = *program_;
    const GLuint tp = shader.id();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, frame.width, frame.height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(tp);
    // The metered exposure, where this frame has one (manual: the shader does not read it).
    if (autoExposure_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, ctx.id(resources::Exposure));
    glProgramUniform1i(tp, shader.uniform("uAutoExposure"), autoExposure_ ? 1 : 0);
    glProgramUniform1f(tp, shader.uniform("uExposure"), std::exp2(frame.params.getFloat("output.exposure")));
    glProgramUniform1i(tp, shader.uniform("uOperator"), tonemapperIndex(frame.params));
    ctx.bindTexture(tp, shader.uniform("uHdr"), resources::CameraHdr);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return {};
}

} // namespace lpv::renderer
