// The indirect light as graph nodes: the sun's RSM, the local lights' RSMs,
// the emissive VPLs, the sky's height map, the LPV's stages (injection, sky
// injection, normals, geometry volume, propagation, bounces) and the
// subsurface LPV; with gi.method = radiosity instead, a baked solution drawn
// from the camera. planIndirect() decides what the scene calls for (each
// decision with its reason); declareIndirect() and declareBakedRadiosity()
// turn that into passes.
#include "frame/ForwardRendererImpl.h"

#include "lpv/radiosity/BakedSolution.h"
#include "lpv/renderer/LocalLightAnalysis.h"
#include "lpv/renderer/lpv/EmissiveVpls.h"

#include <algorithm>

namespace lpv::renderer {

using scene::Pass;

namespace {

// A resource a pass owns, described by asking GL when the graph needs it.
void importTexture(graph::FrameGraph& g, std::string name, std::function<GLuint()> id) {
    g.importResource(std::move(name), [id = std::move(id)] {
        const GLuint t = id();
        return graph::ImportedView{t, graph::queryTexture(t)};
    });
}

} // namespace

scene::Expected<void> ForwardRenderer::Impl::planIndirect(const FrameContext& frame) {
    plan = {};
    const scene::ParameterSet& params = frame.params;
    plan.radiosity = decideBakedRadiosity(params, baked ? baked->mesh.size() : 0, baked ? baked->residual : 0.0);
    if (!giMethodRuns(params)) {
        plan.lpvOffReason = giMethodLpvOffReason(params);
        if (showsBakedRadiosity(params)) {
            frameEffects.push_back(plan.radiosity);
            plan.lpvOffReason = plan.radiosity.runs()
                                    ? "gi.method is radiosity: the indirect light is " + plan.radiosity.reason
                                    : "gi.method is radiosity, but " + plan.radiosity.reason;
        }
        return {};
    }
    plan.sun = findSun(frame.scene) >= 0;
    plan.local = decideLocalLightInjection(frame.scene, params);
    plan.emissive = decideEmissiveInjection(frame.scene, params, frame.worldMagnitude());
    if (!plan.sun && !plan.local.runs() && !plan.emissive.runs()) {
        plan.lpvOffReason = "nothing to inject: no directional light; local lights: " + plan.local.reason +
                            "; emissive surfaces: " + plan.emissive.reason;
        return {};
    }
    if (params.getFloat("lpv.intensity") <= 0.0) {
        plan.lpvOffReason = "lpv.intensity is 0";
        return {};
    }
    // The analysis skips an LPV that cannot reach the scene (issue #41): it
    // would cost its passes and add nothing.
    if (lpvDelivery.skipsLpv()) {
        plan.lpvOffReason = lpvDelivery.reason;
        return {};
    }
    plan.settings = LpvSettings::fromParameters(params);
    // One volume per RSM tile, as far as lpv.cascades asks; the tiles follow the camera.
    const int count = std::min(params.getInt("rsm.cascades"), params.getInt("lpv.cascades"));
    // The RSM's tiles and the LPV's volumes share one placement; the RSM may have more (rsm.cascades).
    plan.rsmCascades = lpvCascades(frame.camera.position, frame.camera.target - frame.camera.position,
                                   lpvCascadeSettings(params, params.getInt("rsm.cascades"), frame.sceneBounds));
    plan.cascades.assign(plan.rsmCascades.begin(), plan.rsmCascades.begin() + count);
    frameEffects.push_back(plan.local);
    frameEffects.push_back(plan.emissive);
    frameEffects.push_back(decideBounces(params, true));
    if (!traits)
        traits = analyseSceneTraits(frame.scene);
    plan.sky = decideSkyInjection(frame.scene, *traits, params);
    frameEffects.push_back(decideDirectedPropagation(params, true, ""));
    frameEffects.push_back(plan.sky);
    plan.sss = decideSubsurface(*traits, params, true, "");
    if (plan.sss.wanted && !plan.sun) {
        plan.sss.wanted = false;
        plan.sss.reason += "; but it is injected from the sun's RSM and no directional light lights the scene";
    }
    if (plan.sss.wanted && !subsurfaceSampler) {
        plan.sss.wanted = false;
        plan.sss.reason += "; but this GL has fewer than 17 fragment texture units for its volume";
    }
    frameEffects.push_back(plan.sss);
    // The volumes are fitted before the graph runs: their size is part of every LPV pass's key.
    if (auto ok = lpv->prepare(plan.settings, plan.cascades); !ok)
        return ok;
    if (!lpv->active()) {
        plan.lpvOffReason = "no RSM to inject from";
        return {};
    }
    plan.lpvRuns = true;
    plan.cameraGv = plan.settings.gvFromCamera && !plan.settings.gvFromScene && gBufferValid;
    return {};
}

LpvRsmInput ForwardRenderer::Impl::rsmInput(const FrameContext& frame) const {
    LpvRsmInput input;
    input.cascades = lpv->cascades();
    if (rsm->active()) {
        for (std::size_t k = 0; k < input.cascades.size() && k < rsm->tiles().size(); ++k)
            input.texelArea.push_back(rsm->tiles()[k].texelArea);
        input.tileSize = rsm->tileSize();
        input.position = rsm->positionArray();
        input.normal = rsm->normalArray();
        input.flux = rsm->fluxArray();
        input.towardSun = -glm::normalize(frame.scene.lights[std::size_t(rsm->sunIndex())].direction);
    }
    return input;
}

const LpvSceneGeometry& ForwardRenderer::Impl::sceneGeometryFor(const FrameContext& frame) {
    // At most 2^24 surfels per level: about 10 M cover Sponza or Sibenik at 0.125 m.
    constexpr std::size_t kMaxSurfelsPerLevel = std::size_t(1) << 24;
    std::vector<float> cellSizes;
    for (const LpvCascade& c : plan.cascades)
        cellSizes.push_back(c.cellSize);
    sceneGvCache.update(frame.scene, cellSizes, kMaxSurfelsPerLevel);
    const lpvref::SceneGv& gv = sceneGvCache.gv();
    // One buffer for every cascade's window, kept from frame to frame.
    const std::size_t cascades = std::min(plan.cascades.size(), gv.levels.size());
    std::size_t offset = 0;
    for (std::size_t k = 0; k < cascades; ++k) {
        const std::size_t m = std::size_t(plan.cascades[k].gridSize) + 1;
        offset += m * m * m;
    }
    sceneGeometry.windows.resize(offset);
    offset = 0;
    for (std::size_t k = 0; k < cascades; ++k) {
        const LpvCascade& c = plan.cascades[k];
        const std::size_t m = std::size_t(c.gridSize) + 1;
        lpvref::windowInto(gv.levels[k], {c.origin, c.cellSize, c.gridSize},
                           std::span<glm::vec4>(sceneGeometry.windows).subspan(offset, m * m * m));
        offset += m * m * m;
    }
    sceneGeometry.surfels = gv.surfels.empty() ? 0 : gv.surfels.front();
    return sceneGeometry;
}

std::vector<LpvLocalInput> ForwardRenderer::Impl::localInputs() const {
    std::vector<LpvLocalInput> local;
    if (localRsm && localRsm->active())
        local.push_back({localRsm->positionArray(), localRsm->normalArray(), localRsm->fluxArray(), localRsm->size(),
                         localRsm->layers(),
                         std::to_string(localRsm->layers()) + " local-light RSM face" +
                             (localRsm->layers() == 1 ? "" : "s")});
    if (emissiveVpls && !emissiveVpls->empty())
        local.push_back(emissiveVpls->input());
    return local;
}

void ForwardRenderer::Impl::declareIndirect(const FrameContext& frame) {
    const LpvSettings& settings = plan.settings;
    const bool lpvRuns = plan.lpvRuns;
    const std::string off = "the LPV does not run: " + plan.lpvOffReason;
    graph::ContentHash base; // what every LPV pass is computed within: the scene, its lights, the volumes
    base.add(sceneGeneration).add(lpv->volumesGeneration()).add(plan.cascades);
    addLights(base, frame.scene.lights);

    // --- The sun's RSM ---
    for (const char* name : {"rsm.position", "rsm.normal", "rsm.flux"})
        importTexture(graph, name, [this, n = std::string(name)] {
            return n == "rsm.position" ? rsm->positionArray() : n == "rsm.normal" ? rsm->normalArray() : rsm->fluxArray();
        });
    {
        graph::PassSpec p;
        p.id = Pass::Rsm;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.sun ? runsBecause("the sun lights the scene") : skippedBecause("no directional light");
        p.writes = {"rsm.position", "rsm.normal", "rsm.flux"};
        graph::ContentHash h;
        // The tiles follow the cascades (the camera's position, its view with lpv.viewShift).
        h.add(sceneGeneration).add(plan.rsmCascades);
        addLights(h, frame.scene.lights);
        p.inputsKey = h.value();
        p.execute = [this](graph::PassContext& ctx) {
            return rsm->render(ctx.frame, *sceneGpu, *materialGpu, plan.rsmCascades);
        };
        graph.addPass(std::move(p));
    }
    // --- Spot and point lights' RSMs ---
    for (const char* name : {"localRsm.position", "localRsm.normal", "localRsm.flux"})
        importTexture(graph, name, [this, n = std::string(name)] {
            if (!localRsm)
                return GLuint(0);
            return n == "localRsm.position" ? localRsm->positionArray()
                   : n == "localRsm.normal" ? localRsm->normalArray()
                                            : localRsm->fluxArray();
        });
    const bool local = lpvRuns && plan.local.runs();
    {
        graph::PassSpec p;
        p.id = Pass::LocalRsm;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.local;
        p.writes = {"localRsm.position", "localRsm.normal", "localRsm.flux"};
        graph::ContentHash h;
        h.add(sceneGeneration);
        addLights(h, frame.scene.lights);
        p.inputsKey = h.value();
        p.execute = [this](graph::PassContext& ctx) -> scene::Expected<void> {
            if (!localRsm) {
                auto created = LocalRsmPass::create();
                if (!created)
                    return std::unexpected(created.error());
                localRsm.emplace(std::move(*created));
            }
            return localRsm->render(ctx.frame, *sceneGpu, *materialGpu, ctx.frame.params.getInt("lpv.localRsmSize"));
        };
        graph.addPass(std::move(p));
    }
    // --- Emissive surfaces' VPLs (sampled on the CPU, uploaded once per scene and cell size) ---
    importTexture(graph, "emissiveVpls", [this] { return emissiveVpls ? emissiveVpls->input().position : 0u; });
    const bool emissive = lpvRuns && plan.emissive.runs();
    {
        graph::PassSpec p;
        p.id = Pass::EmissiveVpls;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.emissive;
        p.writes = {"emissiveVpls"};
        p.inputsKey = graph::ContentHash().add(sceneGeneration).value();
        p.execute = [this](graph::PassContext& ctx) {
            // Two VPLs per finest cell along an emitter, at most 256^2.
            emissiveVpls.emplace();
            emissiveVpls->upload(lpvref::sampleEmissiveVpls(
                ctx.frame.scene, float(ctx.frame.params.getFloat("lpv.cellSize")) * 0.5f, 65536,
                ctx.frame.worldMagnitude()));
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    // --- The sky's height map ---
    importTexture(graph, "skyHeight", [this] { return skyInput ? skyInput->depth : 0u; });
    {
        graph::PassSpec p;
        p.id = Pass::SkyHeight;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.sky;
        p.writes = {"skyHeight"};
        p.inputsKey = graph::ContentHash().add(sceneGeneration).add(plan.cascades).value();
        p.execute = [this](graph::PassContext& ctx) -> scene::Expected<void> {
            if (!skyHeight) {
                auto created = SkyHeightPass::create();
                if (!created)
                    return std::unexpected(created.error());
                skyHeight.emplace(std::move(*created));
            }
            auto rendered = skyHeight->render(ctx.frame, *sceneGpu, *materialGpu, plan.cascades.back(),
                                              SkyHeightPass::resolutionFor(plan.settings.gridSize,
                                                                           int(plan.cascades.size())));
            if (!rendered)
                return std::unexpected(rendered.error());
            skyInput = *rendered;
            return {};
        };
        graph.addPass(std::move(p));
    }

    // --- The LPV's stages, updating its volumes in place ---
    const LpvVolumes& volumes = lpv->volumes();
    importTexture(graph, "lpv.volumes", [&volumes] { return volumes.volume[0].channel[0].id(); });
    importTexture(graph, "lpv.accumulator", [&volumes] { return volumes.accumulator.channel[0].id(); });
    importTexture(graph, "lpv.geometry", [&volumes] { return volumes.geometry.id(); });
    importTexture(graph, "lpv.normals", [&volumes] { return volumes.normals[0].id(); });
    const std::uint64_t lpvKey = base.value();
    // A visualizer that reads the volumes back watches the computation itself: no reuse while it does.
    const std::optional<std::uint64_t> propagationKey =
        lpv->capturing() ? std::nullopt : std::optional<std::uint64_t>(lpvKey);
    const EffectDecision lpvDecision = lpvRuns ? runsBecause(plan.sun ? "the sun's RSM" : "local lights or emissive surfaces")
                                               : skippedBecause(plan.lpvOffReason);
    {
        graph::PassSpec p;
        p.id = Pass::LpvInjection;
        p.decision = lpvDecision;
        if (plan.sun)
            p.reads = {"rsm.position", "rsm.normal", "rsm.flux"};
        if (local)
            p.reads.insert(p.reads.end(), {"localRsm.position", "localRsm.normal", "localRsm.flux"});
        if (emissive)
            p.reads.push_back("emissiveVpls");
        p.writes = {"lpv.volumes", "lpv.accumulator"};
        p.inputsKey = lpvKey;
        p.execute = [this](graph::PassContext& ctx) {
            lpv->injectStage(rsmInput(ctx.frame), localInputs(), plan.settings.directed);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    {
        graph::PassSpec p;
        p.id = Pass::SkyInjection;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.sky;
        p.reads = {"skyHeight", "lpv.volumes", "lpv.accumulator"};
        p.writes = {"lpv.volumes", "lpv.accumulator"};
        p.inputsKey = graph::ContentHash().add(lpvKey).add(frame.scene.sky).value();
        p.execute = [this](graph::PassContext& ctx) {
            LpvSkyInput input = *skyInput;
            input.radiance = ctx.frame.scene.sky.color * ctx.frame.scene.sky.intensity;
            lpv->skyStage(input);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    {
        graph::PassSpec p;
        p.id = Pass::LpvNormals;
        p.decision = !lpvRuns ? skippedBecause(off)
                     : settings.directed ? runsBecause("directed propagation")
                                         : skippedBecause("lpv.directedPropagation is off");
        p.reads = {"lpv.volumes"}; // the VPL normals summed at injection
        p.writes = {"lpv.normals"};
        p.inputsKey = lpvKey;
        p.execute = [this](graph::PassContext&) {
            lpv->normalsStage(plan.settings.directedDilation);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    {
        graph::PassSpec p;
        p.id = Pass::GeometryVolume;
        // Bounces reflect at the GV's surfels, so they need it even without occlusion.
        p.decision = !lpvRuns ? skippedBecause(off)
                     : settings.geometryVolumeRuns() ? runsBecause("lpv.occlusion or lpv.bounces > 1")
                                                                   : skippedBecause("lpv.occlusion is off and one bounce");
        if (plan.sun && !settings.gvFromScene)
            p.reads = {"rsm.position", "rsm.normal"};
        if (plan.cameraGv)
            p.readsHistory = {"camera.depth", "camera.normal"};
        p.writes = {"lpv.geometry"};
        p.inputsKey = lpvKey;
        p.execute = [this](graph::PassContext& ctx) {
            if (plan.settings.gvFromScene)
                lpv->geometryStage(rsmInput(ctx.frame), nullptr, &sceneGeometryFor(ctx.frame));
            else
                lpv->geometryStage(rsmInput(ctx.frame), plan.cameraGv ? &previousCamera : nullptr);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    {
        graph::PassSpec p;
        p.id = Pass::LpvPropagation;
        p.decision = lpvDecision;
        p.reads = {"lpv.volumes", "lpv.accumulator"};
        if (settings.geometryVolumeRuns())
            p.reads.push_back("lpv.geometry");
        if (settings.directed)
            p.reads.push_back("lpv.normals");
        p.writes = {"lpv.volumes", "lpv.accumulator"};
        p.inputsKey = propagationKey;
        p.execute = [this](graph::PassContext&) {
            lpv->propagationStage(plan.settings);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    {
        graph::PassSpec p;
        p.id = Pass::LpvBounces;
        p.decision = !lpvRuns ? skippedBecause(off)
                     : settings.bounces > 1 ? runsBecause("lpv.bounces = " + std::to_string(settings.bounces))
                                            : skippedBecause("lpv.bounces is 1");
        p.reads = {"lpv.volumes", "lpv.accumulator", "lpv.geometry"};
        p.writes = {"lpv.volumes", "lpv.accumulator"};
        p.inputsKey = propagationKey;
        p.execute = [this](graph::PassContext&) {
            lpv->bounceStage(plan.settings);
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    }
    // --- The subsurface LPV, fed by the sun's RSM (its translucent texels) ---
    importTexture(graph, "subsurface.accumulator", [this] { return subsurface ? subsurface->accumulatorTexture() : 0u; });
    {
        graph::PassSpec p;
        p.id = Pass::Subsurface;
        p.decision = !lpvRuns ? skippedBecause(off) : plan.sss;
        p.reads = {"rsm.position", "rsm.normal", "rsm.flux", "lpv.volumes"};
        p.writes = {"subsurface.accumulator"};
        p.inputsKey = lpvKey;
        p.execute = [this](graph::PassContext& ctx) -> scene::Expected<void> {
            if (!subsurface) {
                auto created = LpvSubsurfacePass::create();
                if (!created)
                    return std::unexpected(created.error());
                subsurface.emplace(std::move(*created));
            }
            subsurface->run(LpvSubsurfaceSettings::fromParameters(ctx.frame.params), *lpv, rsmInput(ctx.frame));
            return {};
        };
        graph.addPass(std::move(p));
    }
}

void ForwardRenderer::Impl::declareBakedRadiosity(const FrameContext& frame, bool prepass) {
    const bool runs = plan.radiosity.runs();
    graph::PassSpec p;
    p.id = Pass::RadiosityIndirect;
    p.decision = plan.radiosity;
    p.writes = {"radiosity.incident", "radiosity.depth"};
    if (runs) {
        // Kept across frames, so a still camera reuses them.
        for (const auto& [name, format] : {std::pair{"radiosity.incident", GL_RGBA16F},
                                           std::pair{"radiosity.depth", GL_DEPTH_COMPONENT32F}})
            graph.createResource(name, {graph::ResourceKind::Texture2D, GLenum(format), frame.width, frame.height},
                                 graph::Lifetime::History);
    } else {
        // Named, so the report and --dump can say why they hold nothing; not allocated.
        for (const char* name : {"radiosity.incident", "radiosity.depth"})
            graph.importResource(name, [] { return graph::ImportedView{}; });
    }
    if (prepass)
        p.reads = {"camera.depth"};
    // radiosity.smoothing is declared as invalidating shading (the radiosity
    // view's); here the corner values are uploaded from it, so it is part of
    // what this pass's output is computed from.
    const bool smooth = frame.params.getBool("radiosity.smoothing");
    graph::ContentHash h;
    h.add(sceneGeneration).add(bakedGeneration).add(smooth).add(frame.viewProj).add(frame.camera.position)
        .add(frame.width).add(frame.height);
    p.inputsKey = h.value();
    p.execute = [this, prepass, smooth](graph::PassContext& ctx) -> scene::Expected<void> {
        if (!radiosityIndirect) {
            auto created = RadiosityIndirectPass::create();
            if (!created)
                return std::unexpected(created.error());
            radiosityIndirect.emplace(std::move(*created));
        }
        radiosityIndirect->upload(*baked, bakedGeneration, ctx.frame.scene, smooth);
        radiosityIndirect->render(ctx, prepass);
        return {};
    };
    graph.addPass(std::move(p));
}

void ForwardRenderer::Impl::releaseCulled() {
    if (!graph.produced(Pass::Rsm))
        rsm->release();
    if (!graph.produced(Pass::LocalRsm))
        localRsm.reset();
    if (!graph.produced(Pass::EmissiveVpls))
        emissiveVpls.reset();
    if (!graph.produced(Pass::SkyHeight)) {
        skyHeight.reset();
        skyInput.reset();
    }
    if (!graph.produced(Pass::Subsurface))
        subsurface.reset();
    if (!graph.produced(Pass::SunRays))
        sunRays.reset();
    if (!graph.produced(Pass::RadiosityIndirect))
        radiosityIndirect.reset();
    if (!plan.lpvRuns)
        lpv->disable(plan.lpvOffReason);
}

} // namespace lpv::renderer
