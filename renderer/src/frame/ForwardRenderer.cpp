#include "lpv/renderer/ForwardRenderer.h"

#include "frame/ForwardRendererImpl.h"
#include "gl/GpuMemoryLedger.h"
#include "gl/ImageRows.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

ForwardRenderer::ForwardRenderer() : impl_(std::make_unique<Impl>()) {}
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;
ForwardRenderer::~ForwardRenderer() = default;

Expected<ForwardRenderer> ForwardRenderer::create() {
    ForwardRenderer r;
    auto lpv = LpvPass::create();
    if (!lpv) return std::unexpected(lpv.error());
    r.impl_->lpv.emplace(std::move(*lpv));
    r.impl_->graph.reserveUnits(MaterialGpu::kBaseColorUnit, 15); // MaterialGpu binds these per draw
    if (auto table = r.impl_->buildPassTable(); !table)
        return std::unexpected(table.error());
    return r;
}

const scene::Scene& ForwardRenderer::Impl::enterRenderSpace(const scene::Scene& world) {
    if (sceneBoundsGeneration != sceneGeneration) {
        worldBounds = world.worldBounds();
        sceneBoundsGeneration = sceneGeneration;
    }
    const glm::dvec3 before = space.anchor();
    const scene::Scene& rs = space.update(world, worldBounds, sceneGeneration);
    sceneBounds = worldBounds.empty() ? scene::Bounds{}
                                      : scene::Bounds{space.toRender(worldBounds.min), space.toRender(worldBounds.max)};
    if (space.anchor() != before)
        gBufferValid = false; // last frame's G-buffer holds positions of the old render space
    return rs;
}

void ForwardRenderer::setScene(const scene::Scene& scene, const scene::TextureImages& textures) {
    impl_->traits.reset();
    impl_->exposure->meter().reset();
    ++impl_->sceneGeneration;
    impl_->sceneGvCache.clear(); // another scene's meshes
    impl_->space.setScene(scene);
    const scene::Scene& rs = impl_->enterRenderSpace(scene);
    impl_->sceneGpu = std::make_unique<SceneGpu>(rs);
    impl_->materialGpu = std::make_unique<MaterialGpu>(rs, textures);
}

void ForwardRenderer::updateObjects(const scene::Scene& scene) {
    impl_->traits.reset(); // moved or hidden objects can open or close the sky
    ++impl_->sceneGeneration;
    if (!impl_->sceneGpu)
        return setScene(scene);
    impl_->sceneGpu->updateDraws(impl_->enterRenderSpace(scene));
}

void ForwardRenderer::updateMaterials(const scene::Scene& scene, const scene::TextureImages& textures) {
    impl_->traits.reset();
    ++impl_->sceneGeneration;
    if (!impl_->sceneGpu)
        return setScene(scene, textures);
    const scene::Scene& rs = impl_->enterRenderSpace(scene);
    impl_->materialGpu = std::make_unique<MaterialGpu>(rs, textures);
    impl_->sceneGpu->updateDraws(rs); // buckets follow the materials' alpha modes
}

void ForwardRenderer::setBakedRadiosity(std::shared_ptr<const radiosity::BakedSolution> solution) {
    if (solution == impl_->baked)
        return;
    impl_->baked = std::move(solution);
    ++impl_->bakedGeneration;
}

const radiosity::BakedSolution* ForwardRenderer::bakedRadiosity() const { return impl_->baked.get(); }

void ForwardRenderer::setExposureTimeStep(std::optional<double> seconds) { impl_->exposure->setTimeStep(seconds); }
void ForwardRenderer::resetExposure() { impl_->exposure->meter().reset(); }
double ForwardRenderer::displayExposure(const scene::ParameterSet& params) const {
    const double compensation = std::exp2(params.getFloat("output.exposure"));
    return params.getEnum("output.exposureMode") == "auto" ? compensation * impl_->exposure->meter().readExposure()
                                                           : compensation;
}

GpuTimer& ForwardRenderer::timer() { return impl_->timer; }
int ForwardRenderer::width() const { return impl_->width; }
int ForwardRenderer::height() const { return impl_->height; }
DrawListStats ForwardRenderer::cameraDrawStats() const { return impl_->shading->cameraStats(); }
int ForwardRenderer::shadowCascadesDrawn() const {
    return impl_->graph.status(scene::Pass::ShadowMaps) == PassStatus::Ran ? impl_->shadows->maps().cascadesDrawn() : 0;
}
int ForwardRenderer::shadowCascadesStale() const { return impl_->shadows->maps().staleCascades(); }
std::string ForwardRenderer::lpvNote() const {
    // The LPV's line, then how its size was chosen, then why it delivers
    // (almost) nothing when it does not: a silent zero is a bug to a user.
    return impl_->lpv->note() + fitNote(impl_->lpvFit, impl_->lpvDelivery);
}
const LpvFit& ForwardRenderer::lpvFit() const { return impl_->lpvFit; }
const LpvDelivery& ForwardRenderer::lpvDelivery() const { return impl_->lpvDelivery; }
std::size_t ForwardRenderer::subsurfaceAllocatedBytes() const {
    const LpvSubsurfacePass* volume = impl_->subsurface->volume();
    return volume ? volume->allocatedBytes() : 0;
}
GpuMemory ForwardRenderer::gpuMemory() const {
    const Impl& m = *impl_;
    GpuMemoryLedger ledger;
    // The passes name what they own first, in the table's order, so the
    // graph's one representative of a set (lpv.volumes is the first of six
    // textures) counts under the set's name. The LPV's volumes, which its
    // stages share, count where the stages begin.
    bool lpvNamed = false;
    for (const std::unique_ptr<FramePass>& pass : m.passes) {
        if (!lpvNamed && dynamic_cast<const LpvStage*>(pass.get())) {
            m.lpv->addGpuMemory(ledger);
            lpvNamed = true;
        }
        pass->addGpuMemory(ledger);
    }
    // Then every resource the frame graph declared: its own targets and what the passes imported.
    for (const std::string& name : m.graph.resourceNames())
        if (const std::optional<graph::ResourceDesc> desc = m.graph.resourceDesc(name))
            ledger.addResource(name, m.graph.resourceId(name), *desc);
    return ledger.finish();
}
const std::vector<EffectDecision>& ForwardRenderer::frameEffects() const { return impl_->frameEffects; }

void ForwardRenderer::setShadowCascadeTint(bool on) { impl_->shading->setShadowCascadeTint(on); }

void ForwardRenderer::setLpvCapture(std::optional<LpvCaptureRequest> request) { impl_->lpv->setCapture(request); }

const LpvSnapshot* ForwardRenderer::lpvSnapshot() const {
    const auto& snapshot = impl_->lpv->snapshot();
    if (!snapshot)
        return nullptr;
    impl_->worldSnapshot = *snapshot; // in world space, as the visualizers draw it
    impl_->worldSnapshot->frame.origin = impl_->space.toWorld(snapshot->frame.origin);
    return &*impl_->worldSnapshot;
}

std::vector<LpvGridFrame> ForwardRenderer::lpvCascadeFrames() const {
    std::vector<LpvGridFrame> frames = impl_->lpv->cascadeFrames();
    for (LpvGridFrame& f : frames)
        f.origin = impl_->space.toWorld(f.origin);
    return frames;
}

std::vector<DebugImage> ForwardRenderer::debugImages(const std::string& what) const { return impl_->dump(what); }

std::vector<std::string> ForwardRenderer::dumpNames() const { return impl_->dumpNames(); }

Expected<void> ForwardRenderer::render(const scene::Scene& worldScene, const scene::ParameterSet& params,
                                       const scene::Camera& worldCamera, int width, int height) {
    Impl& d = *impl_;
    if (!d.sceneGpu)
        setScene(worldScene);
    if (auto ok = d.checkSize(width, height); !ok)
        return ok;
    d.timer.beginFrame();
    // Every pass works in render space (RenderSpace.h): the scene and the
    // camera moved so that the scene's bounds start at the origin.
    const scene::Scene& scene = d.enterRenderSpace(worldScene);
    const scene::Camera camera = d.space.toRender(worldCamera);
    const glm::mat4 view = camera.view();
    const glm::mat4 projection = camera.projection(float(width) / float(height));
    // Every pass reads the parameters with the LPV's fit written in.
    d.lpvFit = fitLpv(params, d.sceneBounds, camera.position);
    d.frameParams = withFit(params, d.lpvFit);
    d.lpvDelivery = renderer::lpvDelivery(d.lpvFit, params.getInt("lpv.gridSize"), d.sceneBounds, camera.position);
    const FrameContext frame{scene,      d.frameParams,   camera,  width, height, view, projection,
                             projection * view, d.timer, d.sceneBounds, d.space.anchor()};
    d.materialGpu->setAnisotropy(float(params.getInt("output.anisotropy")));
    try {
        // Build the graph, compile, execute.
        d.frameEffects.clear();
        d.graph.beginFrame();
        // Before the plan: a new size means new camera targets, so last
        // frame's G-buffer cannot feed the geometry volume (its textures go
        // when declareCameraTargets makes the new ones; reading them was a
        // GL error on every resize of the editor's view).
        if (width != d.width || height != d.height)
            d.gBufferValid = false;
        if (auto ok = d.planIndirect(frame); !ok)
            return ok;
        d.declareCameraTargets(frame);
        if (!d.traits)
            d.traits = analyseSceneTraits(scene);
        FrameState state{.frame = frame,
                         .graph = d.graph,
                         .effects = d.frameEffects,
                         .sceneGpu = d.sceneGpu.get(),
                         .materialGpu = d.materialGpu.get(),
                         .sceneGeneration = d.sceneGeneration,
                         .traits = &*d.traits,
                         .depthPrepass = frame.params.getBool("output.depthPrepass"),
                         .radiosity = d.plan.radiosity,
                         .baked = d.baked.get(),
                         .bakedGeneration = d.bakedGeneration,
                         .lpv = d.lpvStageInputs(frame),
                         .subsurface = d.plan.sss,
                         .localLights = d.plan.local,
                         .emissive = d.plan.emissive,
                         .rsmCascades = d.plan.rsmCascades};
        for (const std::unique_ptr<FramePass>& pass : d.passes)
            pass->addTo(state);
        if (auto ok = d.graph.compile(d.frameParams, params.getBool("lpv.reuse")); !ok)
            return ok;
        d.releaseCulled();
        if (auto ok = d.graph.execute(frame); !ok)
            return ok;
    } catch (const std::logic_error& e) {
        return makeError(ErrorCode::InvalidValue, "render", "frame graph", e.what());
    }
    if (d.plan.lpvRuns) {
        if (d.graph.status(scene::Pass::LpvPropagation) == PassStatus::Reused)
            d.lpv->reuse();
        else
            d.lpv->finish(d.plan.settings, d.plan.cameraGv, d.plan.sky.runs(), d.localInputs());
    }
    d.previousCamera = {d.graph.resourceId(resources::CameraDepth), d.graph.resourceId(resources::CameraNormal),
                        glm::inverse(frame.viewProj), camera.position,
                        2.0f * std::tan(0.5f * camera.fovY) / float(height)};
    d.gBufferValid = true;
    d.gBufferSceneGeneration = d.sceneGeneration;

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
        return makeError(ErrorCode::IoError, "render", "OpenGL", "GL error 0x" + std::to_string(err) + " during the frame");
    return {};
}

const FrameGraphReport& ForwardRenderer::graphReport() const { return impl_->graph.report(); }

void ForwardRenderer::blitTo(GLuint framebuffer, int width, int height) const {
    glBlitNamedFramebuffer(impl_->tonemap->framebuffer(), framebuffer, 0, 0, impl_->width, impl_->height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void ForwardRenderer::blitRegionTo(GLuint framebuffer, int srcX0, int srcY0, int srcX1, int srcY1, int dstX0, int dstY0,
                                   int dstX1, int dstY1) const {
    glBlitNamedFramebuffer(impl_->tonemap->framebuffer(), framebuffer, srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

namespace {

std::vector<float> readFloats(GLuint texture, GLenum format, int channels, int width, int height) {
    std::vector<float> px(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    glGetTextureImage(texture, 0, format, GL_FLOAT, GLsizei(px.size() * sizeof(float)), px.data());
    flipRows(px, width, height, channels);
    return px;
}

} // namespace

std::vector<float> ForwardRenderer::readHdr() const {
    return readFloats(impl_->graph.resourceId(resources::CameraHdr), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readGBufferNormal() const {
    return readFloats(impl_->graph.resourceId(resources::CameraNormal), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readGBufferAlbedo() const {
    return readFloats(impl_->graph.resourceId(resources::CameraAlbedo), GL_RGBA, 4, impl_->width, impl_->height);
}
std::vector<float> ForwardRenderer::readDepth() const {
    return readFloats(impl_->graph.resourceId(resources::CameraDepth), GL_DEPTH_COMPONENT, 1, impl_->width, impl_->height);
}

std::vector<std::uint8_t> ForwardRenderer::readDisplay() const {
    std::vector<std::uint8_t> px(std::size_t(impl_->width) * std::size_t(impl_->height) * 4);
    glGetTextureImage(impl_->graph.resourceId(resources::Display), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    flipRows(px, impl_->width, impl_->height, 4);
    return px;
}

} // namespace lpv::renderer
