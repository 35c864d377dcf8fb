#include "lpv/renderer/ForwardRenderer.h"

#include "AutoExposurePass.h"
#include "FrameContext.h"
#include "GlossyReflections.h"
#include "EmissiveVplBuffer.h"
#include "LocalRsmPass.h"
#include "LpvPass.h"
#include "LpvSubsurfacePass.h"
#include "LpvReuseKey.h"
#include "SkyHeightPass.h"
#include "MaterialGpu.h"
#include "RsmPass.h"
#include "ShadowPass.h"
#include "SunRaysPass.h"
#include "lpv/renderer/AutoExposure.h"
#include "lpv/renderer/LocalLightAnalysis.h"
#include "lpv/renderer/lpv/EmissiveVpls.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/scene/AreaLight.h"
#include "lpv/scene/LtcSpecular.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

constexpr int kMaxLights = 8;
// Texture units of the LPV accumulators in the forward pass (after the shadow
// maps and material textures; 16 samplers in the fragment stage in all).
constexpr GLuint kLpvFirstUnit = 16;
// The subsurface LPV's packed accumulator: a 17th fragment sampler, so only
// where GL_MAX_TEXTURE_IMAGE_UNITS allows it (lpv_subsurface_lookup.glsl).
constexpr GLuint kLpvSubsurfaceUnit = kLpvFirstUnit + 3;
constexpr GLint kSamplersWithSubsurface = 17;
// The area lights' LTC table (area_light.glsl's LtcGgxTable): a storage
// buffer, as the fragment stage has no sampler left for it.
constexpr GLuint kLtcTableBinding = 3;

GLint loc(GLuint program, const std::string& name) { return glGetUniformLocation(program, name.c_str()); }

// output.view as forward.frag's uOutputView.
int outputViewIndex(const std::string& name) {
    if (name == "indirect") return 1;
    if (name == "direct") return 2;
    return 0;
}

int tonemapperIndex(const std::string& name) {
    if (name == "aces") return 0;
    if (name == "reinhard") return 1;
    if (name == "uncharted2") return 2;
    return 3;
}

void setLightUniforms(GLuint fp, const scene::Scene& scene) {
    const int lightCount = std::min<int>(int(scene.lights.size()), kMaxLights);
    glProgramUniform1i(fp, loc(fp, "uLightCount"), lightCount);
    for (int i = 0; i < lightCount; ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        const std::string idx = "[" + std::to_string(i) + "]";
        glProgramUniform1i(fp, loc(fp, "uLightType" + idx), int(l.type));
        if (l.type == scene::LightType::Area) {
            const scene::AreaLightFrame f = scene::areaLightFrame(l);
            const glm::vec3 radiance = scene::areaLightRadiance(l);
            glProgramUniform3fv(fp, loc(fp, "uLightRadiantColor" + idx), 1, glm::value_ptr(radiance));
            glProgramUniform3fv(fp, loc(fp, "uLightPosition" + idx), 1, glm::value_ptr(f.center));
            glProgramUniform3fv(fp, loc(fp, "uLightDirection" + idx), 1, glm::value_ptr(f.normal));
            glProgramUniform3fv(fp, loc(fp, "uLightHalfU" + idx), 1, glm::value_ptr(f.halfU));
            glProgramUniform3fv(fp, loc(fp, "uLightHalfV" + idx), 1, glm::value_ptr(f.halfV));
            glProgramUniform1i(fp, loc(fp, "uLightAreaShape" + idx), l.shape == scene::AreaShape::Disc ? 1 : 0);
            glProgramUniform1i(fp, loc(fp, "uLightTwoSided" + idx), l.twoSided ? 1 : 0);
            continue;
        }
        const glm::vec3 radiant = l.color * l.intensity;
        glProgramUniform3fv(fp, loc(fp, "uLightRadiantColor" + idx), 1, glm::value_ptr(radiant));
        glProgramUniform3fv(fp, loc(fp, "uLightPosition" + idx), 1, glm::value_ptr(l.position));
        glProgramUniform3fv(fp, loc(fp, "uLightDirection" + idx), 1, glm::value_ptr(l.direction));
        glProgramUniform1f(fp, loc(fp, "uLightRange" + idx), l.range);
        glProgramUniform2f(fp, loc(fp, "uLightCosCone" + idx), std::cos(l.outerConeAngle),
                           std::cos(std::min(l.innerConeAngle, l.outerConeAngle - 1e-3f)));
    }
}

} // namespace

struct ForwardRenderer::Impl {
    Program forwardProgram, tonemapProgram;
    std::optional<ShadowPass> shadows;
    std::optional<RsmPass> rsm;
    std::optional<LpvPass> lpv;
    // Created on the first frame that wants sun rays: a pass that never runs allocates nothing.
    std::optional<SunRaysPass> sunRays;
    // Auto exposure's meter (output.exposureMode = auto); its result stays on the GPU.
    std::optional<AutoExposurePass> exposure;
    // The GGX LTC table for area lights' specular lobe (scene/LtcSpecular.h), uploaded once.
    Buffer ltcTable;
    // Seconds between this frame and the last, for the exposure's adaptation
    // (nullopt: each frame is metered on its own, as `lpv render` does).
    std::optional<double> exposureTimeStep;
    // Sky light injection's top-down depth map, likewise created on first use
    // and dropped again when the sky is not injected.
    std::optional<SkyHeightPass> skyHeight;
    // The subsurface LPV: created on the first frame that wants it, dropped when not.
    std::optional<LpvSubsurfacePass> subsurface;
    bool subsurfaceSampler = true; // forward.frag has the subsurface sampler (enough texture units)
    // Spot and point lights' RSMs, created while they are injected and dropped when not.
    std::optional<LocalRsmPass> localRsm;
    // Emissive surfaces' VPLs, sampled when the scene or lpv.cellSize changes; empty while not injected.
    std::optional<EmissiveVplBuffer> emissiveVpls;
    std::uint64_t emissiveGeneration = 0;
    double emissiveCellSize = 0.0;
    // What the scene's geometry says (open sky...): rays are cast once per scene change.
    std::optional<SceneTraits> traits;
    // What the LPV in the volumes was computed from; bumped / reset on scene changes.
    std::uint64_t sceneGeneration = 0;
    std::optional<LpvReuseKey> lpvKey;
    std::uint64_t gBufferSceneGeneration = 0; // the scene the camera G-buffer shows
    std::vector<EffectDecision> frameEffects;
    bool glossyRuns = false; // this frame's glossy reflections decision, for the forward pass
    std::unique_ptr<SceneGpu> sceneGpu;
    std::unique_ptr<MaterialGpu> materialGpu;
    GpuTimer timer;
    bool shadowCascadeTint = false; // the visualizers' view of the sun's shadow cascades
    VertexArray emptyVao;
    DrawListStats cameraStats;
    // The camera G-buffer as the last forward pass left it: the LPV injects
    // blocking potential from it before this frame's forward pass runs.
    bool gBufferValid = false;
    LpvCameraInput previousCamera;

    // Camera targets: HDR colour + G-buffer (normal, albedo) + depth, and the display image.
    int width = 0, height = 0;
    Texture hdrColor, gNormal, gAlbedo, depth, display;
    Framebuffer hdrFbo, displayFbo;

    Expected<void> ensureTargets(int w, int h) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (w <= 0 || h <= 0 || w > maxSize || h > maxSize)
            return makeError(ErrorCode::OutOfRange, "render", "size",
                             std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(maxSize) +
                                 " (GL_MAX_TEXTURE_SIZE)");
        if (w == width && h == height)
            return {};
        width = w;
        height = h;
        gBufferValid = false;
        auto target = [&](Texture& t, GLenum format) {
            t = createTexture(GL_TEXTURE_2D);
            glTextureStorage2D(t.id(), 1, format, w, h);
            glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        };
        target(hdrColor, GL_RGBA16F);
        target(gNormal, GL_RGBA16F);
        target(gAlbedo, GL_RGBA8);
        target(depth, GL_DEPTH_COMPONENT32F);
        target(display, GL_RGBA8);
        hdrFbo = createFramebuffer();
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT0, hdrColor.id(), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT1, gNormal.id(), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_COLOR_ATTACHMENT2, gAlbedo.id(), 0);
        glNamedFramebufferTexture(hdrFbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
        glNamedFramebufferDrawBuffers(hdrFbo.id(), 3, buffers);
        displayFbo = createFramebuffer();
        glNamedFramebufferTexture(displayFbo.id(), GL_COLOR_ATTACHMENT0, display.id(), 0);
        if (glGetError() == GL_OUT_OF_MEMORY)
            return makeError(ErrorCode::OutOfRange, "render", "camera targets", "the GPU ran out of memory allocating them");
        return {};
    }

    void renderForward(const FrameContext& frame) {
        frame.timer.begin("forward");
        const GLuint fp = forwardProgram.id();
        glBindFramebuffer(GL_FRAMEBUFFER, hdrFbo.id());
        glViewport(0, 0, frame.width, frame.height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        const int view = outputViewIndex(frame.params.getEnum("output.view"));
        // The indirect view's background is no light, not the sky colour.
        const glm::vec3 sky = view == 1 ? glm::vec3(0.0f) : frame.scene.sky.color * frame.scene.sky.intensity;
        const float background[] = {sky.r, sky.g, sky.b, 1.0f};
        const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 0, background);
        glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 1, zero);
        glClearNamedFramebufferfv(hdrFbo.id(), GL_COLOR, 2, zero);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUseProgram(fp);
        glProgramUniformMatrix4fv(fp, loc(fp, "uViewProj"), 1, GL_FALSE, glm::value_ptr(frame.viewProj));
        glProgramUniform3fv(fp, loc(fp, "uCameraPos"), 1, glm::value_ptr(frame.camera.position));
        glProgramUniform1i(fp, loc(fp, "uOutputView"), view);
        setLightUniforms(fp, frame.scene);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLtcTableBinding, ltcTable.id());
        shadows->bindForShading(fp, frame, 0);
        lpv->bindForShading(fp, frame.params, kLpvFirstUnit);
        if (subsurface && lpv->active())
            subsurface->bindForShading(fp, kLpvSubsurfaceUnit);
        else if (subsurfaceSampler)
            LpvSubsurfacePass::bindNone(fp, kLpvSubsurfaceUnit);
        bindGlossyReflections(fp, frame.params, glossyRuns);
        glProgramUniform1i(fp, loc(fp, "uShadowCascadeTint"), shadowCascadeTint ? 1 : 0);
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
            glDepthMask(GL_TRUE);
        }
        frame.timer.end("forward");
    }

    // gi.method = off: no indirect pass runs, and none holds GPU memory.
    void releaseIndirectPasses(const std::string& reason) {
        rsm->release();
        localRsm.reset();
        emissiveVpls.reset();
        skyHeight.reset();
        subsurface.reset();
        lpvKey.reset();
        lpv->disable(reason);
    }

    Expected<void> runLpv(const FrameContext& frame) {
        if (!giMethodRuns(frame.params)) {
            releaseIndirectPasses("gi.method is off: direct light only");
            return {};
        }
        const EffectDecision local = decideLocalLightInjection(frame.scene, frame.params);
        const EffectDecision emissive = decideEmissiveInjection(frame.scene, frame.params);
        if (!local.runs())
            localRsm.reset(); // a pass that does not run holds no GPU memory
        if (!emissive.runs())
            emissiveVpls.reset();
        if (!rsm->active() && !local.runs() && !emissive.runs()) {
            lpvKey.reset();
            subsurface.reset();
            lpv->disable("nothing to inject: no directional light; local lights: " + local.reason +
                         "; emissive surfaces: " + emissive.reason);
            return {};
        }
        if (frame.params.getFloat("lpv.intensity") <= 0.0) {
            lpvKey.reset();
            subsurface.reset();
            lpv->disable("lpv.intensity is 0");
            return {};
        }
        // Tile k feeds cascade k: lpv.cascades volumes, as far as there are tiles (rsm.cascades).
        LpvRsmInput input;
        if (rsm->active()) {
            const std::size_t cascades =
                std::min(rsm->tiles().size(), std::size_t(frame.params.getInt("lpv.cascades")));
            for (std::size_t k = 0; k < cascades; ++k) {
                input.cascades.push_back(rsm->tiles()[k].cascade);
                input.texelArea.push_back(rsm->tiles()[k].texelArea);
            }
            input.tileSize = rsm->tileSize();
            input.position = rsm->positionArray();
            input.normal = rsm->normalArray();
            input.flux = rsm->fluxArray();
            input.towardSun = -glm::normalize(frame.scene.lights[std::size_t(rsm->sunIndex())].direction);
        } else {
            input.cascades = localLightCascades(frame);
        }
        const LpvSettings settings = LpvSettings::fromParameters(frame.params);
        frameEffects.push_back(local);
        frameEffects.push_back(emissive);
        frameEffects.push_back(decideBounces(frame.params, true));

        if (!traits)
            traits = analyseSceneTraits(frame.scene);
        EffectDecision sky = decideSkyInjection(frame.scene, *traits, frame.params);
        frameEffects.push_back(decideDirectedPropagation(frame.params, true, ""));
        frameEffects.push_back(sky);
        EffectDecision sss = decideSubsurface(*traits, frame.params, true, "");
        if (sss.wanted && !rsm->active()) {
            sss.wanted = false;
            sss.reason += "; but it is injected from the sun's RSM and no directional light lights the scene";
        }
        if (sss.wanted && !subsurfaceSampler) {
            sss.wanted = false;
            sss.reason += "; but this GL has fewer than 17 fragment texture units for its volume";
        }
        frameEffects.push_back(sss);
        // Nothing the LPV is computed from changed: the volumes still hold this frame's answer.
        LpvReuseKey key{sceneGeneration, frame.scene.lights, frame.scene.sky, lpvParameterValues(frame.params),
                        input.cascades, settings.occlusion && settings.gvFromCamera && gBufferValid,
                        glm::mat4(1.0f), 0};
        if (key.cameraGv) {
            key.cameraInverseViewProj = previousCamera.inverseViewProj;
            key.gBufferGeneration = gBufferSceneGeneration;
        }
        // A visualizer that reads the volumes back watches the computation itself: no reuse while it does.
        if (frame.params.getBool("lpv.reuse") && !lpv->capturing() && lpv->active() && lpvKey && *lpvKey == key) {
            lpv->reuse();
            return {};
        }
        lpvKey.reset();
        std::optional<LpvSkyInput> skyInput;
        if (sky.runs() && !input.cascades.empty()) {
            if (!skyHeight) {
                auto created = SkyHeightPass::create();
                if (!created)
                    return std::unexpected(created.error());
                skyHeight.emplace(std::move(*created));
            }
            auto rendered = skyHeight->render(frame, *sceneGpu, *materialGpu, input.cascades.back(),
                                              SkyHeightPass::resolutionFor(settings.gridSize,
                                                                           int(input.cascades.size())));
            if (!rendered)
                return std::unexpected(rendered.error());
            skyInput = *rendered;
            skyInput->radiance = frame.scene.sky.color * frame.scene.sky.intensity;
        } else {
            skyHeight.reset(); // a pass that does not run holds no GPU memory
        }
        std::vector<LpvLocalInput> localInput;
        if (local.runs()) {
            if (!localRsm) {
                auto created = LocalRsmPass::create();
                if (!created)
                    return std::unexpected(created.error());
                localRsm.emplace(std::move(*created));
            }
            if (auto ok = localRsm->render(frame, *sceneGpu, *materialGpu, frame.params.getInt("lpv.localRsmSize"));
                !ok)
                return ok;
            if (localRsm->active())
                localInput.push_back({localRsm->positionArray(), localRsm->normalArray(), localRsm->fluxArray(),
                                      localRsm->size(), localRsm->layers(),
                                      std::to_string(localRsm->layers()) + " local-light RSM face" +
                                          (localRsm->layers() == 1 ? "" : "s")});
        }
        if (emissive.runs()) {
            const double cellSize = frame.params.getFloat("lpv.cellSize");
            if (!emissiveVpls || emissiveGeneration != sceneGeneration || emissiveCellSize != cellSize) {
                // Two VPLs per finest cell along an emitter, at most 256^2.
                emissiveVpls.emplace();
                emissiveVpls->upload(lpvref::sampleEmissiveVpls(frame.scene, float(cellSize) * 0.5f, 65536));
                emissiveGeneration = sceneGeneration;
                emissiveCellSize = cellSize;
            }
            if (!emissiveVpls->empty())
                localInput.push_back(emissiveVpls->input());
        }
        auto ran = lpv->run(settings, input, gBufferValid ? &previousCamera : nullptr, frame.timer,
                            skyInput ? &*skyInput : nullptr, localInput);
        // The subsurface volume is fed by the sun's RSM (its translucent texels).
        if (ran && lpv->active() && sss.runs() && rsm->active()) {
            if (auto ok = runSubsurface(frame, input); !ok)
                return ok;
        } else {
            subsurface.reset(); // a pass that does not run holds no GPU memory
        }
        if (ran && lpv->active())
            lpvKey = std::move(key);
        return ran;
    }

    Expected<void> runSubsurface(const FrameContext& frame, const LpvRsmInput& input) {
        if (!subsurface) {
            auto created = LpvSubsurfacePass::create();
            if (!created)
                return std::unexpected(created.error());
            subsurface.emplace(std::move(*created));
        }
        subsurface->run(LpvSubsurfaceSettings::fromParameters(frame.params), *lpv, input, frame.timer);
        return {};
    }

    // Without a sun there are no RSM tiles to place the cascades: placed around the camera as RsmPass would.
    static std::vector<LpvCascade> localLightCascades(const FrameContext& frame) {
        const int count = std::min(frame.params.getInt("rsm.cascades"), frame.params.getInt("lpv.cascades"));
        const LpvCascadeSettings settings{count, frame.params.getInt("lpv.gridSize"),
                                          float(frame.params.getFloat("lpv.cellSize")),
                                          frame.params.getBool("lpv.cellSnapping")};
        return lpvCascades(frame.camera.position, settings);
    }

    void renderTonemap(const FrameContext& frame) {
        frame.timer.begin("tonemap");
        const GLuint tp = tonemapProgram.id();
        glBindFramebuffer(GL_FRAMEBUFFER, displayFbo.id());
        glViewport(0, 0, frame.width, frame.height);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(tp);
        const bool autoExposure = frame.params.getEnum("output.exposureMode") == "auto";
        if (autoExposure) {
            const double blend = exposureTimeStep
                                     ? adaptationBlend(*exposureTimeStep, frame.params.getFloat("output.exposureAdaptation"))
                                     : 1.0;
            exposure->meter(hdrColor.id(), frame.width, frame.height, float(frame.params.getFloat("output.exposureKey")),
                            float(blend));
        } else {
            exposure->reset(); // back on auto, the exposure starts from its target
        }
        glUseProgram(tp);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, exposure->exposureBuffer());
        glProgramUniform1i(tp, loc(tp, "uAutoExposure"), autoExposure ? 1 : 0);
        glProgramUniform1f(tp, loc(tp, "uExposure"), std::exp2(frame.params.getFloat("output.exposure")));
        glProgramUniform1i(tp, loc(tp, "uOperator"), tonemapperIndex(frame.params.getEnum("output.tonemapper")));
        glProgramUniform1i(tp, loc(tp, "uHdr"), 0);
        glBindTextureUnit(0, hdrColor.id());
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        frame.timer.end("tonemap");
    }
};

ForwardRenderer::ForwardRenderer() : impl_(std::make_unique<Impl>()) {}
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;
ForwardRenderer::~ForwardRenderer() = default;

Expected<ForwardRenderer> ForwardRenderer::create() {
    ForwardRenderer r;
    auto shadows = ShadowPass::create();
    if (!shadows) return std::unexpected(shadows.error());
    GLint fragmentUnits = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragmentUnits);
    r.impl_->subsurfaceSampler = fragmentUnits >= kSamplersWithSubsurface;
    auto forward = buildEmbeddedProgram({"forward.vert", "forward.frag"},
                                        r.impl_->subsurfaceSampler
                                            ? std::vector<std::string>{}
                                            : std::vector<std::string>{"LPV_NO_SUBSURFACE_SAMPLER 1"});
    if (!forward) return std::unexpected(forward.error());
    auto tonemap = buildEmbeddedProgram({"fullscreen.vert", "tonemap.frag"});
    if (!tonemap) return std::unexpected(tonemap.error());
    auto rsm = RsmPass::create();
    if (!rsm) return std::unexpected(rsm.error());
    auto exposure = AutoExposurePass::create();
    if (!exposure) return std::unexpected(exposure.error());
    r.impl_->exposure.emplace(std::move(*exposure));
    r.impl_->ltcTable = createBuffer();
    const std::span<const float> ltc = scene::ltcGgxTable();
    glNamedBufferStorage(r.impl_->ltcTable.id(), GLsizeiptr(ltc.size_bytes()), ltc.data(), 0);
    auto lpv = LpvPass::create();
    if (!lpv) return std::unexpected(lpv.error());
    r.impl_->lpv.emplace(std::move(*lpv));
    r.impl_->shadows.emplace(std::move(*shadows));
    r.impl_->rsm.emplace(std::move(*rsm));
    r.impl_->forwardProgram = std::move(*forward);
    r.impl_->tonemapProgram = std::move(*tonemap);
    r.impl_->emptyVao = createVertexArray();
    return r;
}

void ForwardRenderer::setScene(const scene::Scene& scene, const scene::TextureImages& textures) {
    impl_->traits.reset();
    impl_->exposure->reset();
    ++impl_->sceneGeneration;
    impl_->sceneGpu = std::make_unique<SceneGpu>(scene);
    impl_->materialGpu = std::make_unique<MaterialGpu>(scene, textures);
}

void ForwardRenderer::updateObjects(const scene::Scene& scene) {
    impl_->traits.reset(); // moved or hidden objects can open or close the sky
    ++impl_->sceneGeneration;
    if (!impl_->sceneGpu)
        return setScene(scene);
    impl_->sceneGpu->updateDraws(scene);
}

void ForwardRenderer::updateMaterials(const scene::Scene& scene, const scene::TextureImages& textures) {
    impl_->traits.reset();
    ++impl_->sceneGeneration;
    if (!impl_->sceneGpu)
        return setScene(scene, textures);
    impl_->materialGpu = std::make_unique<MaterialGpu>(scene, textures);
    impl_->sceneGpu->updateDraws(scene); // buckets follow the materials' alpha modes
}

void ForwardRenderer::setExposureTimeStep(std::optional<double> seconds) { impl_->exposureTimeStep = seconds; }
void ForwardRenderer::resetExposure() { impl_->exposure->reset(); }
double ForwardRenderer::displayExposure(const scene::ParameterSet& params) const {
    const double compensation = std::exp2(params.getFloat("output.exposure"));
    return params.getEnum("output.exposureMode") == "auto" ? compensation * impl_->exposure->readExposure()
                                                           : compensation;
}

GpuTimer& ForwardRenderer::timer() { return impl_->timer; }
int ForwardRenderer::width() const { return impl_->width; }
int ForwardRenderer::height() const { return impl_->height; }
DrawListStats ForwardRenderer::cameraDrawStats() const { return impl_->cameraStats; }
std::string ForwardRenderer::lpvNote() const { return impl_->lpv->note(); }
std::size_t ForwardRenderer::subsurfaceAllocatedBytes() const {
    return impl_->subsurface ? impl_->subsurface->allocatedBytes() : 0;
}
const std::vector<EffectDecision>& ForwardRenderer::frameEffects() const { return impl_->frameEffects; }

void ForwardRenderer::setShadowCascadeTint(bool on) { impl_->shadowCascadeTint = on; }

void ForwardRenderer::setLpvCapture(std::optional<LpvCaptureRequest> request) { impl_->lpv->setCapture(request); }

const LpvSnapshot* ForwardRenderer::lpvSnapshot() const {
    const auto& snapshot = impl_->lpv->snapshot();
    return snapshot ? &*snapshot : nullptr;
}

std::vector<LpvGridFrame> ForwardRenderer::lpvCascadeFrames() const { return impl_->lpv->cascadeFrames(); }

std::vector<DebugImage> ForwardRenderer::debugImages(const std::string& what) const {
    if (what == "shadow")
        return impl_->shadows->debugImages();
    if (what == "rsm")
        return impl_->rsm->debugImages();
    if (what == "lpv")
        return impl_->lpv->debugImages();
    if (what == "localrsm")
        return impl_->localRsm ? impl_->localRsm->debugImages() : std::vector<DebugImage>{};
    return {};
}

Expected<void> ForwardRenderer::render(const scene::Scene& scene, const scene::ParameterSet& params,
                                       const scene::Camera& camera, int width, int height) {
    Impl& d = *impl_;
    if (!d.sceneGpu)
        setScene(scene);
    if (auto ok = d.ensureTargets(width, height); !ok)
        return ok;
    d.timer.beginFrame();
    const glm::mat4 view = camera.view();
    const glm::mat4 projection = camera.projection(float(width) / float(height));
    const FrameContext frame{scene, params, camera, width, height, view, projection, projection * view, d.timer};

    d.materialGpu->setAnisotropy(float(params.getInt("output.anisotropy")));
    if (auto ok = d.shadows->render(frame, *d.sceneGpu, *d.materialGpu); !ok)
        return ok;
    if (giMethodRuns(params)) {
        if (auto ok = d.rsm->render(frame, *d.sceneGpu, *d.materialGpu); !ok)
            return ok;
    }
    d.frameEffects.clear();
    if (auto ok = d.runLpv(frame); !ok)
        return ok;
    if (!d.traits)
        d.traits = analyseSceneTraits(scene);
    d.frameEffects.push_back(decideGlossyReflections(*d.traits, params, d.lpv->active(), d.lpv->note()));
    d.glossyRuns = d.frameEffects.back().runs();
    d.renderForward(frame);
    d.previousCamera = {d.depth.id(), d.gNormal.id(), glm::inverse(frame.viewProj), camera.position,
                        2.0f * std::tan(0.5f * camera.fovY) / float(height)};
    d.gBufferValid = true;
    d.gBufferSceneGeneration = d.sceneGeneration;
    d.frameEffects.push_back(decideSunRays(scene, params, &camera, float(width) / float(height)));
    if (d.frameEffects.back().runs()) {
        if (!d.sunRays) {
            auto created = SunRaysPass::create();
            if (!created)
                return std::unexpected(created.error());
            d.sunRays.emplace(std::move(*created));
        }
        d.sunRays->render(frame, d.depth.id(), d.hdrColor.id(), *sunOf(scene));
    }
    d.renderTonemap(frame);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
        return makeError(ErrorCode::IoError, "render", "OpenGL", "GL error 0x" + std::to_string(err) + " during the frame");
    return {};
}

void ForwardRenderer::blitTo(GLuint framebuffer, int width, int height) const {
    glBlitNamedFramebuffer(impl_->displayFbo.id(), framebuffer, 0, 0, impl_->width, impl_->height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void ForwardRenderer::blitRegionTo(GLuint framebuffer, int srcX0, int srcY0, int srcX1, int srcY1, int dstX0, int dstY0,
                                   int dstX1, int dstY1) const {
    glBlitNamedFramebuffer(impl_->displayFbo.id(), framebuffer, srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

namespace {

template <class T>
void flipRows(std::vector<T>& pixels, int width, int height, int channels) {
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row));
}

std::vector<float> readFloats(GLuint texture, GLenum format, int channels, int width, int height) {
    std::vector<float> px(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    glGetTextureImage(texture, 0, format, GL_FLOAT, GLsizei(px.size() * sizeof(float)), px.data());
    flipRows(px, width, height, channels);
    return px;
}

} // namespace

std::vector<float> ForwardRenderer::readHdr() const {
    return readFloats(impl_->hdrColor.id(), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readGBufferNormal() const {
    return readFloats(impl_->gNormal.id(), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readGBufferAlbedo() const {
    return readFloats(impl_->gAlbedo.id(), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readDepth() const {
    return readFloats(impl_->depth.id(), GL_DEPTH_COMPONENT, 1, impl_->width, impl_->height);
}

std::vector<std::uint8_t> ForwardRenderer::readDisplay() const {
    std::vector<std::uint8_t> px(std::size_t(impl_->width) * std::size_t(impl_->height) * 4);
    glGetTextureImage(impl_->display.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    flipRows(px, impl_->width, impl_->height, 4);
    return px;
}

} // namespace lpv::renderer
