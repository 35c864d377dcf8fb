#include "passes/radiosity/RadiosityIndirectPass.h"

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

scene::Expected<RadiosityIndirectPass> RadiosityIndirectPass::create() {
    auto program = buildEmbeddedProgram({"radiosity_indirect.vert", "radiosity_indirect.frag"});
    if (!program)
        return std::unexpected(program.error());
    RadiosityIndirectPass pass;
    pass.program_ = std::move(*program);
    return pass;
}

void RadiosityIndirectPass::upload(const radiosity::BakedSolution& solution, std::uint64_t generation,
                                   const scene::Scene& scene, bool smooth) {
    if (uploaded_ && generation_ == generation && smooth_ == smooth)
        return;
    const std::vector<glm::vec3> corners = radiosity::cornerValues(solution.mesh, solution.incident, smooth);
    draw_ = uploadPatchVertices(patchTriangles(solution.mesh, corners, [&](const radiosity::Patch& p) {
        return p.material >= scene.materials.size() ||
               scene.materials[p.material].alphaMode != scene::AlphaMode::Blend;
    }));
    uploaded_ = true;
    generation_ = generation;
    smooth_ = smooth;
}

void RadiosityIndirectPass::render(graph::PassContext& ctx, bool afterPrepass) {
    const FrameContext& frame = ctx.frame;
    const GLuint incident = ctx.id("radiosity.incident"), depth = ctx.id("radiosity.depth");
    if (attachedIncident_ != incident || attachedDepth_ != depth) {
        // Rebuilt when the graph hands out other targets (a resize).
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, incident, 0);
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth, 0);
        attachedIncident_ = incident;
        attachedDepth_ = depth;
    }
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, none);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // a patch seen from behind still hides what lies behind it
    glDisable(GL_BLEND);
    const GLuint p = program_.id();
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
        ctx.bindTexture(p, loc(p, "uSceneDepth"), "camera.depth");
    if (draw_.vertices > 0) {
        glBindVertexArray(draw_.vao.id());
        glDrawArrays(GL_TRIANGLES, 0, draw_.vertices);
    }
    glBindVertexArray(0);
}

void RadiosityIndirectPass::addGpuMemory(GpuMemoryLedger& ledger) const {
    ledger.addBuffer("radiosity.patches", draw_.buffer.id());
}

} // namespace lpv::renderer
