#include "passes/direct/ShadingPass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "gl/GpuMemoryLedger.h"
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/LtcSpecular.h"
#include "passes/lpv/GlossyReflections.h"
#include "passes/lpv/LpvSubsurfacePass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lpv::renderer {

namespace {

// The subsurface LPV's packed accumulator is a 17th fragment sampler, so only
// where GL_MAX_TEXTURE_IMAGE_UNITS allows it (lpv_subsurface_lookup.glsl).
constexpr GLint kSamplersWithSubsurface = 17;

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

using Lookup = IndirectLight::Lookup;

const IndirectLight* find(const std::vector<IndirectLight>& lights, Lookup lookup) {
    const auto it = std::ranges::find(lights, lookup, &IndirectLight::lookup);
    return it == lights.end() ? nullptr : &*it;
}

// forward.frag's LPV lookup with no LPV behind it: no cascades, and its
// samplers naming a 3D texture unit of their own (nothing reads them).
void bindNoLpv(const CachedProgram& shader, graph::PassContext& ctx) {
    const GLuint program = shader.id();
    glProgramUniform1i(program, shader.uniform("uLpvCascadeCount"), 0);
    glProgramUniform1i(program, shader.uniform("uLpvVisibility"), 0);
    for (const char* sampler : {"uLpvAccumR", "uLpvAccumG", "uLpvAccumB"}) {
        const GLuint unit = ctx.allocateUnit();
        glProgramUniform1i(program, shader.uniform(sampler), GLint(unit));
        glBindTextureUnit(unit, 0);
    }
}

} // namespace

scene::Expected<std::unique_ptr<ShadingPass>> ShadingPass::create() {
    std::unique_ptr<ShadingPass> pass(new ShadingPass());
    GLint fragmentUnits = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragmentUnits);
    pass->subsurfaceSampler_ = fragmentUnits >= kSamplersWithSubsurface;
    if (!pass->subsurfaceSampler_)
        pass->defines_.push_back("LPV_NO_SUBSURFACE_SAMPLER 1");
    for (int afterPrepass = 0; afterPrepass < 2; ++afterPrepass) {
        std::vector<std::string> full = pass->defines_;
        full.push_back("LPV_AREA_LIGHTS 1");
        if (afterPrepass)
            full.push_back("LPV_AFTER_DEPTH_PREPASS 1");
        auto program = pass->programs_.get({{"forward.vert", "forward.frag"}, full});
        if (!program)
            return std::unexpected(program.error());
        pass->full_[std::size_t(afterPrepass)] = *program;
    }
    pass->ltcTable_ = createBuffer();
    const std::span<const float> ltc = scene::ltcGgxTable();
    glNamedBufferStorage(pass->ltcTable_.id(), GLsizeiptr(ltc.size_bytes()), ltc.data(), 0);
    return pass;
}

void ShadingPass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    const bool prepass = state.depthPrepass;
    pass.decision = runsBecause("the image");
    pass.final = true;
    pass.reads = {resources::ShadowMaps};
    if (prepass)
        pass.reads.push_back(resources::CameraDepth);
    // Whatever indirect light this frame's passes declared (IndirectLight.h).
    for (const IndirectLight& light : state.indirectLight)
        pass.reads.insert(pass.reads.end(), light.reads.begin(), light.reads.end());
    pass.writes = {resources::CameraHdr, resources::CameraNormal, resources::CameraAlbedo};
    if (!prepass)
        pass.writes.push_back(resources::CameraDepth);
    // Glossy reflections march through the LPV inside this pass.
    const LpvStageInputs& lpv = state.lpv;
    state.effects.push_back(
        decideGlossyReflections(*state.traits, frame.params, lpv.runs, lpv.runs ? "" : "LPV: off (" + lpv.offReason + ")"));
    glossyRuns_ = state.effects.back().runs();
}

const CachedProgram& ShadingPass::variant(const FrameState& state, const std::vector<std::string>& indirectDefines) {
    const FrameContext& frame = state.frame;
    const std::vector<IndirectLight>& lights = state.indirectLight;
    ProgramVariant variant{{"forward.vert", "forward.frag"}, defines_};
    if (std::ranges::any_of(frame.scene.lights, [](const scene::Light& l) { return l.type == scene::LightType::Area; }))
        variant.defines.push_back("LPV_AREA_LIGHTS 1");
    if (!state.shadowMaps->hasLocalShadows())
        variant.defines.push_back("LPV_NO_LOCAL_SHADOWS 1");
    if (!find(lights, Lookup::LpvVolume))
        variant.defines.push_back("LPV_NO_VISIBILITY 1");
    variant.defines.insert(variant.defines.end(), indirectDefines.begin(), indirectDefines.end());
    if (!glossyRuns_)
        variant.defines.push_back("LPV_NO_GLOSSY 1");
    if (!find(lights, Lookup::SubsurfaceVolume))
        variant.defines.push_back("LPV_NO_SUBSURFACE_LOOKUP 1");
    if (state.depthPrepass)
        variant.defines.push_back("LPV_AFTER_DEPTH_PREPASS 1");
    // An image of the light at each pixel in place of the LPV's lookups (which it compiles out).
    if (find(lights, Lookup::ScreenIncident))
        variant.defines.push_back("LPV_SCREEN_INDIRECT 1");
    // Built on first use (a few hundred ms on llvmpipe); the full shader,
    // built at create(), shades the same image should a variant not build.
    auto program = programs_.get(variant);
    return program ? **program : *full_[state.depthPrepass ? 1 : 0];
}

void ShadingPass::attach(graph::PassContext& ctx) {
    const std::array<GLuint, 4> targets{ctx.id(resources::CameraHdr), ctx.id(resources::CameraNormal),
                                        ctx.id(resources::CameraAlbedo), ctx.id(resources::CameraDepth)};
    if (targets == attached_)
        return;
    fbo_ = createFramebuffer();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, targets[0], 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, targets[1], 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT2, targets[2], 0);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, targets[3], 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo_.id(), 3, buffers);
    attached_ = targets;
}

scene::Expected<void> ShadingPass::execute(graph::PassContext& ctx, FrameState& state) {
    const FrameContext& frame = ctx.frame;
    // After the pre-pass: depth tested before shading, equal to the nearest surface, not written again.
    const bool afterPrepass = state.depthPrepass;
    const std::vector<IndirectLight>& lights = state.indirectLight;
    // An image of the LPV's lookup resolved to each pixel (LpvReducedResolution)
    // describes the opaque surface there: blended draws over it look up themselves.
    std::vector<std::string> solidDefines, blendedDefines;
    for (const IndirectLight& light : lights)
        if (light.defines) {
            light.defines(solidDefines);
            if (light.lookup != Lookup::LpvReducedResolution)
                light.defines(blendedDefines);
        }
    attach(ctx);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
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
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, background);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 2, zero);
    if (!afterPrepass)
        glClear(GL_DEPTH_BUFFER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLtcTableBinding, ltcTable_.id());
    // Sets a variant's uniforms and binds what it samples. Texture units come
    // from the graph, around the units MaterialGpu binds per draw.
    auto prepare = [&](const CachedProgram& shader) {
        const GLuint fp = shader.id();
        glUseProgram(fp);
        glProgramUniformMatrix4fv(fp, shader.uniform("uViewProj"), 1, GL_FALSE, glm::value_ptr(frame.viewProj));
        glProgramUniform3fv(fp, shader.uniform("uCameraPos"), 1, glm::value_ptr(frame.camera.position));
        glProgramUniform1i(fp, shader.uniform("uOutputView"), view);
        setLightUniforms(shader, frame.scene);
        state.shadowMaps->bindForShading(shader, frame, [&ctx] { return ctx.allocateUnit(); });
        // The indirect light: each declared lookup bound by its provider, the
        // others' samplers pointed at nothing (forward.frag still declares them).
        if (const IndirectLight* lpv = find(lights, Lookup::LpvVolume))
            lpv->bind(shader, ctx);
        else
            bindNoLpv(shader, ctx);
        if (const IndirectLight* reduced = find(lights, Lookup::LpvReducedResolution))
            reduced->bind(shader, ctx);
        if (const IndirectLight* subsurface = find(lights, Lookup::SubsurfaceVolume))
            subsurface->bind(shader, ctx);
        else if (subsurfaceSampler_)
            LpvSubsurfacePass::bindNone(shader, ctx.allocateUnit());
        bindGlossyReflections(shader, frame.params, glossyRuns_);
        if (const IndirectLight* screen = find(lights, Lookup::ScreenIncident))
            ctx.bindTexture(fp, shader.uniform("uIndirectIncident"), screen->reads.front());
        glProgramUniform1i(fp, shader.uniform("uShadowCascadeTint"), cascadeTint_ ? 1 : 0);
    };
    const auto items = buildDrawList(state.sceneGpu->draws(), frame.viewProj, frame.camera.position, &stats_);
    // Opaque and masked items first; blended ones (sorted last, back to
    // front) over them with depth test but no depth write, and without
    // touching the G-buffer (it describes the opaque surface behind).
    const auto firstBlended = std::ranges::find_if(items, [](const DrawItem* d) { return d->bucket == DrawBucket::Blended; });
    const std::vector<const DrawItem*> solid(items.begin(), firstBlended), blended(firstBlended, items.end());
    const SceneGpu& scene = *state.sceneGpu;
    MaterialGpu& materials = *state.materialGpu;
    const CachedProgram& solidShader = variant(state, solidDefines);
    prepare(solidShader);
    GLuint fp = solidShader.id();
    scene.draw(fp, solid, [&](std::uint32_t m) { materials.bind(fp, m, MaterialBindMode::Full); });
    if (!blended.empty()) {
        const CachedProgram& blendedShader = blendedDefines == solidDefines ? solidShader : variant(state, blendedDefines);
        if (&blendedShader != &solidShader) {
            prepare(blendedShader);
            fp = blendedShader.id();
        }
        glDepthMask(GL_FALSE);
        glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glColorMaski(2, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnablei(GL_BLEND, 0);
        scene.draw(fp, blended, [&](std::uint32_t m) {
            materials.bind(fp, m, MaterialBindMode::Full);
            // forward.frag writes premultiplied colour: "over" or additive.
            glBlendFunci(0, GL_ONE, materials.additive(m) ? GL_ONE : GL_ONE_MINUS_SRC_ALPHA);
        });
        glDisablei(GL_BLEND, 0);
        glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glColorMaski(2, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return {};
}

void ShadingPass::addGpuMemory(GpuMemoryLedger& ledger) const { ledger.addBuffer("shading.ltcTable", ltcTable_.id()); }

} // namespace lpv::renderer
