#include "passes/radiosity/RadiosityIndirectPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "graph/ContentHash.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/radiosity/BakedSolution.h"
#include "lpv/radiosity/VertexRadiosity.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace lpv::renderer {
namespace {

// How far (relative to the view distance) a patch may lie from the surface
// the depth pre-pass found and still light it. Patches lie in the planes of
// the triangles they were cut from, so only a quad's slight non-planarity
// (its two triangles within 0.8 degrees) and depth rounding separate them;
// 1% keeps a leaf 5 cm in front of a wall 10 m away apart from the wall.
constexpr float kDepthTolerance = 0.01f;

GLint loc(GLuint program, const char* name) {
    return glGetUniformLocation(program, name);
}

} // namespace

void RadiosityIndirectPass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    pass.decision = state.radiosity;
    pass.writes = {Incident, Depth};
    if (state.radiosity.runs()) {
        // Kept across frames, so a still camera reuses them.
        for (const auto& [name, format] : {std::pair{Incident, GL_RGBA16F},
                                           std::pair{Depth, GL_DEPTH_COMPONENT32F}})
            state.graph.createResource(name, {graph::ResourceKind::Texture2D, GLenum(format), frame.width, frame.height},
                                       graph::Lifetime::History);
    } else {
        // Named, so the report and --dump can say why they hold nothing; not allocated.
        for (graph::ResourceHandle name : {Incident, Depth})
            state.graph.importResource(name, [] { return graph::ImportedView{}; });
    }
    if (state.depthPrepass)
        pass.reads = {resources::CameraDepth};
    // Shading reads radiosity.incident at its pixel as the indirect light, in place of the LPV's (frame/IndirectLight.h).
    if (state.radiosity.runs())
        state.indirectLight.push_back(screenIndirectLight(id(), Incident));
    // The corner values are uploaded smoothed or flat (upload()): the graph
    // keys this pass's reuse on the parameter it reads.
    pass.parameters = {"radiosity.smoothing"};
    graph::ContentHash h;
    h.add(state.sceneGeneration).add(state.bakedGeneration).add(frame.viewProj).add(frame.camera.position)
        .add(frame.width).add(frame.height);
    pass.inputsKey = h.value();
}

scene::Expected<void> RadiosityIndirectPass::execute(graph::PassContext& ctx, FrameState& state) {
    if (!gpu_) {
        auto program = buildEmbeddedProgram({"radiosity_indirect.vert", "radiosity_indirect.frag"});
        if (!program)
            return std::unexpected(program.error());
        gpu_.emplace();
        gpu_->program = std::move(*program);
    }
    upload(*state.baked, state.bakedGeneration, ctx.frame.scene, ctx.frame.params.getBool("radiosity.smoothing"));
    render(ctx, state.depthPrepass);
    return {};
}

void RadiosityIndirectPass::upload(const radiosity::BakedSolution& solution, std::uint64_t generation,
                                   const scene::Scene& scene, bool smooth) {
    Gpu& g = *gpu_;
    if (g.uploaded && g.generation == generation && g.smooth == smooth)
        return;
    const std::vector<glm::vec3> corners = radiosity::cornerValues(solution.mesh, solution.incident, smooth);
    g.draw = uploadPatchVertices(patchTriangles(solution.mesh, corners, [&](const radiosity::Patch& p) {
        return p.material >= scene.materials.size() ||
               scene.materials[p.material].alphaMode != scene::AlphaMode::Blend;
    }));
    g.uploaded = true;
    g.generation = generation;
    g.smooth = smooth;
}

void RadiosityIndirectPass::render(graph::PassContext& ctx, bool afterPrepass) {
    const FrameContext& frame = ctx.frame;
    Gpu& g = *gpu_;
    const GLuint incident = ctx.id(Incident), depth = ctx.id(Depth);
    if (g.attachedIncident != incident || g.attachedDepth != depth) {
        // Rebuilt when the graph hands out other targets (a resize).
        g.fbo = createFramebuffer();
        glNamedFramebufferTexture(g.fbo.id(), GL_COLOR_ATTACHMENT0, incident, 0);
        glNamedFramebufferTexture(g.fbo.id(), GL_DEPTH_ATTACHMENT, depth, 0);
        g.attachedIncident = incident;
        g.attachedDepth = depth;
    }
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(g.fbo.id(), GL_COLOR, 0, none);
    glClearNamedFramebufferfv(g.fbo.id(), GL_DEPTH, 0, &farDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, g.fbo.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // a patch seen from behind still hides what lies behind it
    glDisable(GL_BLEND);
    const GLuint p = g.program.id();
    glUseProgram(p);
    // The solution's patches are in world space; the frame's matrices in
    // render space (FrameContext::anchor): move the patches there.
    const glm::mat4 worldViewProj =
        glm::mat4(glm::dmat4(frame.viewProj) * glm::translate(glm::dmat4(1.0), -frame.anchor));
    const glm::vec3 worldCamera = glm::vec3(glm::dvec3(frame.camera.position) + frame.anchor);
    glProgramUniformMatrix4fv(p, loc(p, "uViewProj"), 1, GL_FALSE, glm::value_ptr(worldViewProj));
    glProgramUniform3fv(p, loc(p, "uCameraPos"), 1, glm::value_ptr(worldCamera));
    glProgramUniform1i(p, loc(p, "uTestSceneDepth"), afterPrepass ? 1 : 0);
    glProgramUniform1f(p, loc(p, "uDepthTolerance"), kDepthTolerance);
    glProgramUniform2f(p, loc(p, "uProjectionZ"), frame.projection[2][2], frame.projection[3][2]);
    if (afterPrepass)
        ctx.bindTexture(p, loc(p, "uSceneDepth"), resources::CameraDepth);
    if (g.draw.vertices > 0) {
        glBindVertexArray(g.draw.vao.id());
        glDrawArrays(GL_TRIANGLES, 0, g.draw.vertices);
    }
    glBindVertexArray(0);
}

void RadiosityIndirectPass::addGpuMemory(GpuMemoryLedger& ledger) const {
    if (gpu_)
        ledger.addBuffer("radiosity.patches", gpu_->draw.buffer.id());
}

} // namespace lpv::renderer
