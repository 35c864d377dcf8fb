#include "passes/direct/SunRaysPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace lpv::renderer {
namespace {

// The sun's disc as seen in the occlusion image: a quarter of a degree of
// radius would be a few texels; 1.5 to 2.5 degrees keeps the source visible
// at half resolution and softens its edge.
constexpr float kDiscInnerDegrees = 1.5f;
constexpr float kDiscOuterDegrees = 2.5f;
// Open sky away from the sun, relative to the disc: what makes shafts through gaps in geometry.
constexpr float kSkyLevel = 0.15f;
// Ray strength per unit of sun irradiance (W/m^2) and of averaged occlusion.
constexpr float kRayStrength = 0.6f;

GLint loc(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

} // namespace

scene::Expected<SunRaysPass::Gpu> SunRaysPass::createGpu() {
    Gpu gpu;
    auto occlusion = buildEmbeddedProgram({"fullscreen.vert", "sun_occlusion.frag"});
    if (!occlusion)
        return std::unexpected(occlusion.error());
    auto rays = buildEmbeddedProgram({"fullscreen.vert", "sun_rays.frag"});
    if (!rays)
        return std::unexpected(rays.error());
    gpu.occlusionProgram = std::move(*occlusion);
    gpu.raysProgram = std::move(*rays);
    gpu.emptyVao = createVertexArray();
    return gpu;
}

void SunRaysPass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    state.effects.push_back(
        decideSunRays(frame.scene, frame.params, &frame.camera, float(frame.width) / float(frame.height)));
    pass.decision = state.effects.back();
    state.graph.createResource(resources::SunRaysOcclusion, occlusionTarget(frame.width, frame.height),
                               graph::Lifetime::Transient);
    pass.reads = {resources::CameraDepth, resources::CameraHdr};
    pass.writes = {resources::CameraHdr, resources::SunRaysOcclusion};
}

scene::Expected<void> SunRaysPass::execute(graph::PassContext& ctx, FrameState&) {
    if (auto created = createOnFirstRun(gpu_, &createGpu); !created)
        return created;
    render(ctx.frame, ctx.id(resources::CameraDepth), ctx.id(resources::CameraHdr), ctx.id(resources::SunRaysOcclusion),
           *sunOf(ctx.frame.scene));
    return {};
}

graph::ResourceDesc SunRaysPass::occlusionTarget(int width, int height) {
    graph::ResourceDesc d{graph::ResourceKind::Texture2D, GL_R16F, std::max(width / 2, 1), std::max(height / 2, 1)};
    // Samples between texels blend, and rays that run off the screen read the edge (sky or geometry).
    d.linearFilter = true;
    return d;
}

void SunRaysPass::ensureTargets(GLuint occlusion, GLuint hdrColor) {
    Gpu& g = *gpu_;
    // Framebuffers around the graph's targets, rebuilt when the graph hands out others.
    if (g.attachedOcclusion != occlusion) {
        g.occlusionFbo = createFramebuffer();
        glNamedFramebufferTexture(g.occlusionFbo.id(), GL_COLOR_ATTACHMENT0, occlusion, 0);
        g.attachedOcclusion = occlusion;
    }
    if (g.attachedHdr != hdrColor) {
        g.hdrFbo = createFramebuffer();
        glNamedFramebufferTexture(g.hdrFbo.id(), GL_COLOR_ATTACHMENT0, hdrColor, 0);
        g.attachedHdr = hdrColor;
    }
}

void SunRaysPass::render(const FrameContext& frame, GLuint depth, GLuint hdrColor, GLuint occlusion,
                         const scene::Light& sun) {
    ensureTargets(occlusion, hdrColor);
    Gpu& g = *gpu_;
    const glm::vec3 towardSun = -glm::normalize(sun.direction);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(g.emptyVao.id());

    // 1. Occlusion at half resolution.
    const GLuint op = g.occlusionProgram.id();
    glBindFramebuffer(GL_FRAMEBUFFER, g.occlusionFbo.id());
    glViewport(0, 0, std::max(frame.width / 2, 1), std::max(frame.height / 2, 1));
    glDisable(GL_BLEND);
    glUseProgram(op);
    const glm::mat4 invViewProj = glm::inverse(frame.viewProj);
    glProgramUniformMatrix4fv(op, loc(op, "uInvViewProj"), 1, GL_FALSE, glm::value_ptr(invViewProj));
    glProgramUniform3fv(op, loc(op, "uTowardSun"), 1, glm::value_ptr(towardSun));
    glProgramUniform1f(op, loc(op, "uSkyLevel"), kSkyLevel);
    glProgramUniform2f(op, loc(op, "uDiscCos"), std::cos(glm::radians(kDiscOuterDegrees)),
                       std::cos(glm::radians(kDiscInnerDegrees)));
    glProgramUniform1i(op, loc(op, "uDepth"), 0);
    glBindTextureUnit(0, depth);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // 2. Radial blur towards the sun, added to the HDR colour.
    const glm::vec4 clip = frame.projection * glm::mat4(glm::mat3(frame.view)) * glm::vec4(towardSun, 1.0f);
    const glm::vec2 sunUv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    const GLuint rp = g.raysProgram.id();
    glBindFramebuffer(GL_FRAMEBUFFER, g.hdrFbo.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(rp);
    glProgramUniform2fv(rp, loc(rp, "uSunUv"), 1, glm::value_ptr(sunUv));
    glProgramUniform1i(rp, loc(rp, "uSamples"), frame.params.getInt("effects.sunRaySamples"));
    glProgramUniform1f(rp, loc(rp, "uDensity"), frame.params.getFloat("effects.sunRayDensity"));
    glProgramUniform1f(rp, loc(rp, "uDecay"), frame.params.getFloat("effects.sunRayDecay"));
    const glm::vec3 color = sun.color * sun.intensity * kRayStrength;
    glProgramUniform3fv(rp, loc(rp, "uRayColor"), 1, glm::value_ptr(color));
    glProgramUniform1i(rp, loc(rp, "uOcclusion"), 0);
    glBindTextureUnit(0, occlusion);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
}

} // namespace lpv::renderer
