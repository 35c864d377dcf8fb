// The frame's pass the renderer still declares itself: shading (the forward
// pass that also writes the camera G-buffer), and the camera targets.
// Shadow maps, the depth pre-pass, sun rays, exposure and tonemapping
// declare themselves (passes/direct/).
#include "frame/ForwardRendererImpl.h"

#include "passes/lpv/GlossyReflections.h"
#include "lpv/renderer/AutoExposure.h"
#include "lpv/renderer/DisplayMapping.h"
#include "lpv/scene/AreaLight.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;
using scene::Pass;

namespace {

constexpr int kMaxLights = 8;
// The area lights' LTC table (area_light.glsl's LtcGgxTable): a storage
// buffer, as the fragment stage has no sampler left for it.
constexpr GLuint kLtcTableBinding = 3;

// An enum parameter's position among its registry values: the shaders'
// numbering follows the registry's order. A value the registry does not
// list is a programming error, not a default.
int enumIndex(const scene::ParameterSet& params, const char* key, std::initializer_list<const char*> shaderOrder) {
    const std::string value = params.getEnum(key);
    int i = 0;
    for (const char* name : shaderOrder) {
        if (value == name)
            return i;
        ++i;
    }
    throw std::logic_error(std::string(key) + " = '" + value + "' has no shader index");
}

// output.view as forward.frag's uOutputView.
int outputViewIndex(const scene::ParameterSet& params) {
    return enumIndex(params, "output.view", {"final", "indirect", "direct"});
}

// Uniform names of light i, built once (not per frame).
struct LightUniformNames {
    std::string type, radiant, position, direction, range, cosCone, halfU, halfV, areaShape, twoSided;
};
const LightUniformNames& lightNames(int i) {
    static const std::vector<LightUniformNames> names = [] {
        std::vector<LightUniformNames> all;
        for (int k = 0; k < kMaxLights; ++k) {
            const std::string idx = "[" + std::to_string(k) + "]";
            all.push_back({"uLightType" + idx, "uLightRadiantColor" + idx, "uLightPosition" + idx,
                           "uLightDirection" + idx, "uLightRange" + idx, "uLightCosCone" + idx, "uLightHalfU" + idx,
                           "uLightHalfV" + idx, "uLightAreaShape" + idx, "uLightTwoSided" + idx});
        }
        return all;
    }();
    return names[std::size_t(i)];
}

void setLightUniforms(const CachedProgram& shader, const scene::Scene& scene) {
    const GLuint fp = shader.id();
    const int lightCount = std::min<int>(int(scene.lights.size()), kMaxLights);
    glProgramUniform1i(fp, shader.uniform("uLightCount"), lightCount);
    for (int i = 0; i < lightCount; ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        const LightUniformNames& n = lightNames(i);
        glProgramUniform1i(fp, shader.uniform(n.type), int(l.type));
        if (l.type == scene::LightType::Area) {
            const scene::AreaLightFrame f = scene::areaLightFrame(l);
            const glm::vec3 radiance = scene::areaLightRadiance(l);
            glProgramUniform3fv(fp, shader.uniform(n.radiant), 1, glm::value_ptr(radiance));
            glProgramUniform3fv(fp, shader.uniform(n.position), 1, glm::value_ptr(f.center));
            glProgramUniform3fv(fp, shader.uniform(n.direction), 1, glm::value_ptr(f.normal));
            glProgramUniform3fv(fp, shader.uniform(n.halfU), 1, glm::value_ptr(f.halfU));
            glProgramUniform3fv(fp, shader.uniform(n.halfV), 1, glm::value_ptr(f.halfV));
            glProgramUniform1i(fp, shader.uniform(n.areaShape), l.shape == scene::AreaShape::Disc ? 1 : 0);
            glProgramUniform1i(fp, shader.uniform(n.twoSided), l.twoSided ? 1 : 0);
            continue;
        }
        const glm::vec3 radiant = l.color * l.intensity;
        glProgramUniform3fv(fp, shader.uniform(n.radiant), 1, glm::value_ptr(radiant));
        glProgramUniform3fv(fp, shader.uniform(n.position), 1, glm::value_ptr(l.position));
        glProgramUniform3fv(fp, shader.uniform(n.direction), 1, glm::value_ptr(l.direction));
        glProgramUniform1f(fp, shader.uniform(n.range), l.range);
        glProgramUniform2f(fp, shader.uniform(n.cosCone), std::cos(l.outerConeAngle),
                           std::cos(std::min(l.innerConeAngle, l.outerConeAngle - 1e-3f)));
    }
}

graph::ResourceDesc target2D(GLenum format, int w, int h) {
    return {graph::ResourceKind::Texture2D, format, w, h};
}

} // namespace

scene::Expected<void> ForwardRenderer::Impl::checkSize(int w, int h) const {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (w <= 0 || h <= 0 || w > maxSize || h > maxSize)
        return makeError(ErrorCode::OutOfRange, "render", "size",
                         std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(maxSize) +
                             " (GL_MAX_TEXTURE_SIZE)");
    return {};
}

void ForwardRenderer::Impl::declareCameraTargets(const FrameContext& frame) {
    const int w = frame.width, h = frame.height;
    if (w != width || h != height)
        gBufferValid = false; // the new targets hold nothing yet
    width = w;
    height = h;
    // Last frame's G-buffer, as the geometry volume reads it: named by the camera and scene it shows.
    const std::uint64_t gBufferVersion =
        gBufferValid ? graph::ContentHash().add(previousCamera.inverseViewProj).add(gBufferSceneGeneration).value() : 0;
    using graph::Lifetime;
    graph.createResource(resources::CameraHdr, target2D(GL_RGBA16F, w, h), Lifetime::History);
    graph.createResource(resources::CameraNormal, target2D(GL_RGBA16F, w, h), Lifetime::History, gBufferVersion);
    graph.createResource(resources::CameraAlbedo, target2D(GL_RGBA8, w, h), Lifetime::History);
    graph.createResource(resources::CameraDepth, target2D(GL_DEPTH_COMPONENT32F, w, h), Lifetime::History, gBufferVersion);
    graph.createResource(resources::Display, target2D(GL_RGBA8, w, h), Lifetime::History);
}

void ForwardRenderer::Impl::attachCameraTargets() {
    const GLuint depth = graph.resourceId(resources::CameraDepth);
    if (depth != hdrFboDepth) {
        hdrFbo = createFramebuffer();
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT0, graph.resourceId(resources::CameraHdr), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT1, graph.resourceId(resources::CameraNormal), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT2, graph.resourceId(resources::CameraAlbedo), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_DEPTH_ATTACHMENT, depth, 0);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glNamedFramebufferDrawBuffers(hdrFbo.id(), 3, buffers);
        hdrFboDepth = depth;
    }
}

void ForwardRenderer::Impl::declareShading(const FrameState& state) {
    const FrameContext& frame = state.frame;
    const bool prepass = state.depthPrepass;
    graph::PassSpec p;
    p.id = Pass::Shading;
    p.decision = runsBecause("the image");
    p.final = true;
    p.reads = {resources::ShadowMaps};
    if (prepass)
        p.reads.push_back(resources::CameraDepth);
    if (plan.lpvRuns)
        p.reads.push_back(resources::LpvAccumulator);
    if (plan.lpvRuns && plan.sss.runs())
        p.reads.push_back(resources::SubsurfaceAccumulator);
    if (plan.radiosity.runs())
        p.reads.push_back(resources::RadiosityIncident);
    p.writes = {resources::CameraHdr, resources::CameraNormal, resources::CameraAlbedo};
    if (!prepass)
        p.writes.push_back(resources::CameraDepth);
    // Glossy reflections march through the LPV inside this pass.
    if (!traits)
        traits = analyseSceneTraits(frame.scene);
    frameEffects.push_back(decideGlossyReflections(*traits, frame.params, plan.lpvRuns,
                                                   plan.lpvRuns ? "" : "LPV: off (" + plan.lpvOffReason + ")"));
    glossyRuns = frameEffects.back().runs();
    p.execute = [this, prepass](graph::PassContext& ctx) {
        attachCameraTargets();
        renderForward(ctx, prepass);
        return scene::Expected<void>{};
    };
    graph.addPass(std::move(p));
}

const CachedProgram& ForwardRenderer::Impl::forwardVariant(const FrameContext& frame, bool afterPrepass, bool glossy,
                                                           bool subsurfaceLookup, bool radiosity) {
    ProgramVariant variant{{"forward.vert", "forward.frag"}, forwardDefines};
    if (std::ranges::any_of(frame.scene.lights, [](const scene::Light& l) { return l.type == scene::LightType::Area; }))
        variant.defines.push_back("LPV_AREA_LIGHTS 1");
    if (!shadows->maps().hasLocalShadows())
        variant.defines.push_back("LPV_NO_LOCAL_SHADOWS 1");
    if (!lpv->visibilityBound())
        variant.defines.push_back("LPV_NO_VISIBILITY 1");
    if (!glossy)
        variant.defines.push_back("LPV_NO_GLOSSY 1");
    if (!subsurfaceLookup)
        variant.defines.push_back("LPV_NO_SUBSURFACE_LOOKUP 1");
    if (afterPrepass)
        variant.defines.push_back("LPV_AFTER_DEPTH_PREPASS 1");
    // The baked solution's light in place of the LPV's (which it compiles out).
    if (radiosity)
        variant.defines.push_back("LPV_RADIOSITY 1");
    // Built on first use (a few hundred ms on llvmpipe); the full shader,
    // built at create(), shades the same image should a variant not build.
    auto program = programs.get(variant);
    return program ? **program : *forwardFull[afterPrepass ? 1 : 0];
}

void ForwardRenderer::Impl::renderForward(graph::PassContext& ctx, bool afterPrepass) {
    const FrameContext& frame = ctx.frame;
    // After the pre-pass: depth tested before shading, equal to the nearest surface, not written again.
    const bool radiosity = plan.radiosity.runs();
    const CachedProgram& shader =
        forwardVariant(frame, afterPrepass, glossyRuns, subsurface->volume() && lpv->active(), radiosity);
    const GLuint fp = shader.id();
    glBindFramebuffer(GL_FRAMEBUFFER, hdrFbo.id());
    glViewport(0, 0, frame.width, frame.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(afterPrepass ? GL_LEQUAL : GL_LESS);
    glDepthMask(afterPrepass ? GL_FALSE : GL_TRUE);
    glDisable(GL_CULL_FACE);
    const int view = outputViewIndex(frame.params);
    // The indirect view's background is no light, not the sky colour.
    const glm::vec3 sky = view == 1 ? glm::vec3(0.0f) : frame.scene.sky.color * frame.scene.sky.intensity;
    const float background[] = {sky.r, sky.g, sky.b, 1.0f};
    const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 0, background);
    glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 2, zero);
    if (!afterPrepass)
        glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(fp);
    glProgramUniformMatrix4fv(fp, shader.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(frame.viewProj));
    glProgramUniform3fv(fp, shader.uniform("uCameraPos"), 1, glm::value_ptr(frame.camera.position));
    glProgramUniform1i(fp, shader.uniform("uOutputView"), view);
    setLightUniforms(shader, frame.scene);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLtcTableBinding, ltcTable.id());
    // Texture units come from the graph, around the units MaterialGpu binds per draw.
    const UnitAllocator nextUnit = [&ctx] { return ctx.allocateUnit(); };
    shadows->maps().bindForShading(shader, frame, nextUnit);
    lpv->bindForShading(shader, frame.params, nextUnit);
    if (subsurface->volume() && lpv->active())
        subsurface->volume()->bindForShading(shader, ctx.allocateUnit());
    else if (subsurfaceSampler)
        LpvSubsurfacePass::bindNone(shader, ctx.allocateUnit());
    bindGlossyReflections(shader, frame.params, glossyRuns);
    if (radiosity)
        ctx.bindTexture(fp, shader.uniform("uRadiosityIncident"), resources::RadiosityIncident);
    glProgramUniform1i(fp, shader.uniform("uShadowCascadeTint"), shadowCascadeTint ? 1 : 0);
    const auto items = buildDrawList(sceneGpu->draws(), frame.viewProj, frame.camera.position, &cameraStats);
    // Opaque and masked items first; blended ones (sorted last, back to
    // front) over them with depth test but no depth write, and without
    // touching the G-buffer (it describes the opaque surface behind).
    const auto firstBlended = std::ranges::find_if(items, [](const DrawItem* d) { return d->bucket == DrawBucket::Blended; });
    const std::vector<const DrawItem*> solid(items.begin(), firstBlended), blended(firstBlended, items.end());
    sceneGpu->draw(fp, solid, [&](std::uint32_t m) { materialGpu->bind(fp, m, MaterialBindMode::Full); });
    if (!blended.empty()) {
        glDepthMask(GL_FALSE);
        glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glColorMaski(2, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnablei(GL_BLEND, 0);
        sceneGpu->draw(fp, blended, [&](std::uint32_t m) {
            materialGpu->bind(fp, m, MaterialBindMode::Full);
            // forward.frag writes premultiplied colour: "over" or additive.
            glBlendFunci(0, GL_ONE, materialGpu->additive(m) ? GL_ONE : GL_ONE_MINUS_SRC_ALPHA);
        });
        glDisablei(GL_BLEND, 0);
        glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glColorMaski(2, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

} // namespace lpv::renderer
