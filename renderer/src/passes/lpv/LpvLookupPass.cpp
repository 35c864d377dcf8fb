#include "passes/lpv/LpvLookupPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "frame/SurfaceDrawing.h"
#include "lpv/renderer/DrawList.h"

#include <glm/gtc/type_ptr.hpp>


namespace lpv::renderer {

namespace {

// The low-resolution target's size for a view of `full` pixels: every
// full-resolution pixel has a low-resolution texel over it.
int reducedSize(int full, int reduction) { return (full + reduction - 1) / reduction; }

// What the lookup reads besides the LPV's volumes: the parameters that shading
// passes to lpv_lookup.glsl (LpvPass::bindForShading).
const std::vector<std::string> kLookupParameters{"lpv.intensity",       "lpv.bleedingDamping", "lpv.cascadeBlendLevels",
                                                 "lpv.lookupOffset",    "lpv.visibilityLookup", "lpv.visibilityBias"};

} // namespace

LookupResolutionDecision LpvLookupPass::resolution(const FrameState& state) {
    const FrameContext& frame = state.frame;
    std::size_t triangles = 0;
    for (const scene::Object& object : frame.scene.objects)
        if (object.visible && object.mesh >= 0 && std::size_t(object.mesh) < frame.scene.meshes.size())
            triangles += frame.scene.meshes[std::size_t(object.mesh)].indices.size() / 3;
    return decideLookupResolution(frame.params, frame.width, frame.height, frame.camera.fovY, triangles);
}

void LpvLookupPass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    const LookupResolutionDecision resolution = LpvLookupPass::resolution(state);
    const int reduction = resolution.reduction;
    reduction_ = reduction;
    if (reduction == 1)
        pass.decision = skippedBecause(resolution.reason + ": shading looks the LPV up at every pixel");
    else if (!state.lpv.runs)
        pass.decision = skippedBecause("the LPV does not run: " + state.lpv.offReason);
    else
        pass.decision =
            runsBecause(resolution.reason + ": the LPV's lookup once per " + std::to_string(reduction) + "x" +
                        std::to_string(reduction) + " pixels, upsampled by lpvLookupResolve");
    // The frame's effects list (`lpv render`, the editor) says what auto chose and why, run or reused.
    EffectDecision effect = pass.decision;
    effect.effect = "LPV lookup at reduced resolution";
    effect.parameter = "lpv.lookupResolution";
    effect.setting = frame.params.getEnum("lpv.lookupResolution");
    state.effects.push_back(std::move(effect));
    pass.writes = {resources::LpvLookup, resources::LpvLookupNormal, resources::LpvLookupDepth};
    if (!pass.decision.runs()) {
        // Named, so the report and --dump can say why they hold nothing; not allocated.
        for (graph::ResourceHandle name : pass.writes)
            state.graph.importResource(name, [] { return graph::ImportedView{}; });
        return;
    }
    const int w = reducedSize(frame.width, reduction), h = reducedSize(frame.height, reduction);
    for (const auto& [name, format] :
         {std::pair{resources::LpvLookup, GL_RGBA16F}, std::pair{resources::LpvLookupNormal, GL_RGBA8},
          std::pair{resources::LpvLookupDepth, GL_DEPTH_COMPONENT32F}})
        state.graph.createResource(name, {graph::ResourceKind::Texture2D, GLenum(format), w, h},
                                   graph::Lifetime::History);
    pass.reads = {resources::LpvAccumulator};
    pass.parameters = kLookupParameters;
    pass.inputsKey = state.cameraKey();
    const LpvPass* lpv = state.lpv.lpv;
    visibility_ = lpv->visibilityBound();
}

scene::Expected<void> LpvLookupPass::execute(graph::PassContext& ctx, FrameState& state) {
    const FrameContext& frame = ctx.frame;
    const std::array<GLuint, 3> targets{ctx.id(resources::LpvLookup), ctx.id(resources::LpvLookupNormal),
                                        ctx.id(resources::LpvLookupDepth)};
    if (targets != attached_) {
        // Rebuilt when the graph hands out other targets (a resize, another reduction).
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, targets[0], 0);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, targets[1], 0);
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, targets[2], 0);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo_.id(), 2, buffers);
        attached_ = targets;
    }
    const int reduction = reduction_;
    // No surface: a negative distance and a zero normal, which no pixel's weights accept.
    const float noSurface[] = {0.0f, 0.0f, 0.0f, -1.0f};
    const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, noSurface);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, reducedSize(frame.width, reduction), reducedSize(frame.height, reduction));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    // Opaque and masked surfaces, as the depth pre-pass draws them: blended
    // ones find no neighbour on their surface in shading and look up there.
    const SurfaceDraws draws = surfaceDraws(state.sceneGpu->draws(), frame.viewProj, frame.camera.position);
    // Depth first (depth_prepass.frag, as the camera's pre-pass draws it),
    // then the lookup once per texel with the depth test before the shader:
    // drawn directly, every fragment nearer than what was drawn before it paid for a lookup.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    auto depthDrawn = drawSurfaces(draws, programs_, {{"forward.vert", "depth_prepass.frag"}, {}},
                                   "PREPASS_OPAQUE", state, [](const CachedProgram&) {});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (!depthDrawn)
        return depthDrawn;
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    const LpvPass* lpv = state.lpv.lpv;
    ProgramVariant lookup{{"forward.vert", "lpv_lookup_reduced.frag"}, {}};
    if (!visibility_)
        lookup.defines.push_back("LPV_NO_VISIBILITY 1");
    auto lookedUp =
        drawSurfaces(draws, programs_, lookup, "LOOKUP_OPAQUE", state, [&](const CachedProgram& shader) {
            const GLuint p = shader.id();
            glProgramUniform3fv(p, shader.uniform("uCameraPos"), 1, glm::value_ptr(frame.camera.position));
            glProgramUniform1f(p, shader.uniform("uLpvLowDistanceScale"), 1.0f / frame.camera.farPlane);
            lpv->bindForShading(shader, frame.params, [&ctx] { return ctx.allocateUnit(); });
        });
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return lookedUp;
}

} // namespace lpv::renderer
