#include "passes/lpv/LpvLookupResolvePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "frame/SurfaceDrawing.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/renderer/DrawList.h"
#include "passes/lpv/LpvLookupPass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lpv::renderer {

namespace {

// lpv_lookup_resolve.frag's list: a header (count, then the indirect
// dispatch's x, y, z) and 5 words a pixel, room for an eighth of the view's
// pixels (measured at 1024x600: 0.4-0.9% of Sibenik's and 0.2-0.3% of
// Sponza's at half and quarter; past it a pixel keeps its neighbours' plain mean).
constexpr std::size_t kListHeaderBytes = 4 * sizeof(std::uint32_t);
constexpr std::size_t kListShareOfPixels = 8;
constexpr std::size_t kListMinEntries = 4096;
constexpr std::size_t kEntryBytes = 5 * sizeof(std::uint32_t);
constexpr GLuint kListBinding = 0;
constexpr GLuint kResolvedImageUnit = 0;

// What the fallback lookup reads besides the LPV's volumes (LpvPass::bindForShading).
const std::vector<std::string> kParameters{"lpv.lookupResolution", "lpv.intensity",      "lpv.bleedingDamping",
                                           "lpv.cascadeBlendLevels", "lpv.lookupOffset", "lpv.visibilityLookup",
                                           "lpv.visibilityBias"};

} // namespace

void LpvLookupResolvePass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    const LookupResolutionDecision resolution = LpvLookupPass::resolution(state);
    reduction_ = resolution.reduction;
    if (reduction_ == 1)
        pass.decision = skippedBecause(resolution.reason + ": shading looks the LPV up at every pixel");
    else if (!state.lpv.runs)
        pass.decision = skippedBecause("the LPV does not run: " + state.lpv.offReason);
    else
        pass.decision = runsBecause(
            resolution.reason + ": the lpvLookup image upsampled to every pixel, looked up "
                                "at full resolution where no low-resolution neighbour lies on its surface");
    ownDepth_ = !state.depthPrepass;
    pass.writes = {Resolved, ResolveDepth};
    if (!pass.decision.runs()) {
        // Named, so the report and --dump can say why they hold nothing; not allocated.
        for (graph::ResourceHandle name : pass.writes)
            state.graph.importResource(name, [] { return graph::ImportedView{}; });
        return;
    }
    state.graph.createResource(Resolved,
                               {graph::ResourceKind::Texture2D, GL_RGBA16F, frame.width, frame.height},
                               graph::Lifetime::History);
    if (ownDepth_)
        state.graph.createResource(
            ResolveDepth, {graph::ResourceKind::Texture2D, GL_DEPTH_COMPONENT32F, frame.width, frame.height},
            graph::Lifetime::History);
    else
        state.graph.importResource(ResolveDepth, [] { return graph::ImportedView{}; });
    pass.reads = {resources::LpvLookup, resources::LpvLookupNormal, resources::LpvAccumulator};
    if (!ownDepth_)
        pass.reads.push_back(resources::CameraDepth);
    pass.parameters = kParameters;
    pass.inputsKey = state.cameraKey();
    visibility_ = state.lpv.lpv->visibilityBound();

    // Shading's opaque and masked draws read lpv.resolved at their pixel in
    // place of the LPV's diffuse lookup (forward.frag's LPV_LOOKUP_RESOLVED).
    IndirectLight light;
    light.provider = id();
    light.lookup = IndirectLight::Lookup::LpvReducedResolution;
    light.reads = {Resolved};
    light.defines = [](std::vector<std::string>& defines) { defines.push_back("LPV_LOOKUP_RESOLVED 1"); };
    light.bind = [](const CachedProgram& shader, graph::PassContext& ctx) {
        ctx.bindTexture(shader.id(), shader.uniform("uLpvResolved"), Resolved);
    };
    state.indirectLight.push_back(std::move(light));
}

void LpvLookupResolvePass::reserveList(std::size_t pixels) {
    const std::size_t entries = std::max(kListMinEntries, pixels / kListShareOfPixels);
    if (list_.id() != 0 && entries <= listEntries_)
        return;
    list_ = createBuffer();
    glNamedBufferData(list_.id(), GLsizeiptr(kListHeaderBytes + entries * kEntryBytes), nullptr,
                      GL_DYNAMIC_COPY);
    listEntries_ = entries;
}

scene::Expected<void> LpvLookupResolvePass::execute(graph::PassContext& ctx, FrameState& state) {
    const FrameContext& frame = ctx.frame;
    const GLuint resolved = ctx.id(Resolved);
    const GLuint depth = ctx.id(ownDepth_ ? ResolveDepth : resources::CameraDepth);
    if (std::array{resolved, depth} != attached_) {
        // Rebuilt when the graph hands out other targets (a resize, the pre-pass switched).
        fbo_ = createFramebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, resolved, 0);
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth, 0);
        attached_ = {resolved, depth};
    }
    reserveList(std::size_t(frame.width) * std::size_t(frame.height));
    const std::uint32_t header[4] = {0, 0, 1, 1}; // no pixel listed; the dispatch's x grows with the list
    glNamedBufferSubData(list_.id(), 0, sizeof(header), header);

    const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    // Opaque and masked surfaces, as the depth pre-pass draws them: blended
    // ones look the LPV up in shading.
    const SurfaceDraws draws = surfaceDraws(state.sceneGpu->draws(), frame.viewProj, frame.camera.position);
    if (ownDepth_) {
        // No pre-pass: depth first (depth_prepass.frag), so that the resolve
        // below runs once per pixel, on the surface shading will light there.
        const float farDepth = 1.0f;
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        auto drawn = drawSurfaces(draws, programs_, {{"forward.vert", "depth_prepass.frag"}, {}},
                                  "PREPASS_OPAQUE", state, [](const CachedProgram&) {});
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        if (!drawn)
            return drawn;
    }
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    const int lowW = (frame.width + reduction_ - 1) / reduction_,
              lowH = (frame.height + reduction_ - 1) / reduction_;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kListBinding, list_.id());
    const ProgramVariant resolve{{"forward.vert", "lpv_lookup_resolve.frag"}, {}};
    auto resolvedDraw =
        drawSurfaces(draws, programs_, resolve, "RESOLVE_OPAQUE", state, [&](const CachedProgram& shader) {
            const GLuint p = shader.id();
            glProgramUniform3fv(p, shader.uniform("uCameraPos"), 1, glm::value_ptr(frame.camera.position));
            glProgramUniform2f(p, shader.uniform("uLpvLowScale"), float(lowW) / float(frame.width),
                               float(lowH) / float(frame.height));
            glProgramUniform1f(p, shader.uniform("uLpvLowDistanceScale"), 1.0f / frame.camera.farPlane);
            glProgramUniform1ui(p, shader.uniform("uLpvFallbackCapacity"), GLuint(listEntries_));
            ctx.bindTexture(p, shader.uniform("uLpvLowIrradiance"), resources::LpvLookup);
            ctx.bindTexture(p, shader.uniform("uLpvLowNormal"), resources::LpvLookupNormal);
        });
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    if (!resolvedDraw)
        return resolvedDraw;

    // The listed pixels, looked up at full resolution over their texel.
    ProgramVariant fallbackVariant{{"lpv_lookup_fallback.comp"}, {}};
    if (!visibility_)
        fallbackVariant.defines.push_back("LPV_NO_VISIBILITY 1");
    auto fallback = programs_.get(fallbackVariant);
    if (!fallback)
        return std::unexpected(fallback.error());
    const CachedProgram& shader = **fallback;
    glUseProgram(shader.id());
    state.lpv.lpv->bindForShading(shader, frame.params, [&ctx] { return ctx.allocateUnit(); });
    glBindImageTexture(kResolvedImageUnit, resolved, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, list_.id());
    glDispatchComputeIndirect(sizeof(std::uint32_t)); // the header's x, y, z
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return {};
}

void LpvLookupResolvePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    if (list_.id() != 0)
        ledger.addBuffer("lpvLookupResolve.fallbackList", list_.id());
}

} // namespace lpv::renderer
