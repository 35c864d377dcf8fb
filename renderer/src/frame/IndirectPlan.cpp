// The indirect light: planIndirect() decides what the scene calls for (each
// decision with its reason) and lpvStageInputs() hands that plan to the
// LPV's stages (passes/lpv/LpvStages.h), the sky's height map
// (SkyHeightFramePass), the subsurface LPV (SubsurfaceFramePass) and the
// VPLs' sources (RsmFramePass, LocalRsmFramePass, EmissiveVplsFramePass).
#include "frame/ForwardRendererImpl.h"

#include "lpv/radiosity/BakedSolution.h"
#include "lpv/renderer/LocalLightAnalysis.h"

#include <algorithm>

namespace lpv::renderer {

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
    if (plan.sss.wanted && !shading->hasSubsurfaceSampler()) {
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
    if (const RsmPass& maps = rsm->maps(); maps.active()) {
        for (std::size_t k = 0; k < input.cascades.size() && k < maps.tiles().size(); ++k)
            input.texelArea.push_back(maps.tiles()[k].texelArea);
        input.tileSize = maps.tileSize();
        input.position = maps.positionArray();
        input.normal = maps.normalArray();
        input.flux = maps.fluxArray();
        input.towardSun = -glm::normalize(frame.scene.lights[std::size_t(maps.sunIndex())].direction);
    }
    return input;
}

const LpvSceneGeometry& ForwardRenderer::Impl::sceneGeometryFor(const FrameContext& frame) {
    // At most 2^24 surfels per level: about 10 M cover Sponza or Sibenik at 0.125 m.
    constexpr std::size_t kMaxSurfelsPerLevel = std::size_t(1) << 24;
    std::vector<float> cellSizes;
    for (const LpvCascade& c : plan.cascades)
        cellSizes.push_back(c.cellSize);
    const int bands = plan.settings.shBands; // three: band 2 as well (issue #47)
    sceneGvCache.update(frame.scene, cellSizes, kMaxSurfelsPerLevel, bands);
    const lpvref::SceneGv& gv = sceneGvCache.gv();
    // One buffer for every cascade's window, kept from frame to frame.
    const std::size_t cascades = std::min(plan.cascades.size(), gv.levels.size());
    std::size_t offset = 0;
    for (std::size_t k = 0; k < cascades; ++k) {
        const std::size_t m = std::size_t(plan.cascades[k].gridSize) + 1;
        offset += m * m * m;
    }
    sceneGeometry.windows.resize(offset);
    sceneGeometry.windowsHigh.resize(bands == 3 ? 2 * offset : 0);
    offset = 0;
    for (std::size_t k = 0; k < cascades; ++k) {
        const LpvCascade& c = plan.cascades[k];
        const std::size_t m = std::size_t(c.gridSize) + 1;
        lpvref::windowInto(gv.levels[k], {c.origin, c.cellSize, c.gridSize},
                           std::span<glm::vec4>(sceneGeometry.windows).subspan(offset, m * m * m));
        if (bands == 3)
            lpvref::windowBand2Into(gv.levels[k], {c.origin, c.cellSize, c.gridSize},
                                    std::span<glm::vec4>(sceneGeometry.windowsHigh).subspan(2 * offset, 2 * m * m * m));
        offset += m * m * m;
    }
    sceneGeometry.surfels = gv.surfels.empty() ? 0 : gv.surfels.front();
    return sceneGeometry;
}

std::vector<LpvLocalInput> ForwardRenderer::Impl::localInputs() const {
    std::vector<LpvLocalInput> local;
    if (const LocalRsmPass* faces = localRsm->maps())
        local.push_back({faces->positionArray(), faces->normalArray(), faces->fluxArray(), faces->size(),
                         faces->layers(),
                         std::to_string(faces->layers()) + " local-light RSM face" + (faces->layers() == 1 ? "" : "s")});
    if (const EmissiveVplBuffer* vpls = emissiveVpls->vpls())
        local.push_back(vpls->input());
    return local;
}

LpvStageInputs ForwardRenderer::Impl::lpvStageInputs(const FrameContext& frame) {
    LpvStageInputs in;
    in.lpv = &*lpv;
    in.settings = plan.settings;
    in.runs = plan.lpvRuns;
    in.offReason = plan.lpvOffReason;
    in.sun = plan.sun;
    in.local = plan.lpvRuns && plan.local.runs();
    in.emissive = plan.lpvRuns && plan.emissive.runs();
    in.sky = plan.sky;
    in.cascades = plan.cascades;
    graph::ContentHash base; // what every LPV pass is computed within: the scene, its lights, the volumes
    base.add(sceneGeneration).add(lpv->volumesGeneration()).add(plan.cascades);
    addLights(base, frame.scene.lights);
    in.key = base.value();
    in.skyKey = graph::ContentHash().add(in.key).add(frame.scene.sky).value();
    // A visualizer that reads the volumes back watches the computation itself: no reuse while it does.
    in.propagationKey = lpv->capturing() ? std::nullopt : std::optional<std::uint64_t>(in.key);
    in.rsm = [this, &frame] { return rsmInput(frame); };
    in.localInputs = [this] { return localInputs(); };
    in.skyInput = [this, &frame] {
        // The stage runs only after skyHeight (it reads its output), so the map is there.
        const LpvSkyInput* map = skyHeight->input();
        LpvSkyInput input = map ? *map : LpvSkyInput{};
        input.radiance = frame.scene.sky.color * frame.scene.sky.intensity;
        return input;
    };
    in.cameraGv = plan.cameraGv;
    in.camera = !plan.settings.gvFromScene && plan.cameraGv ? &previousCamera : nullptr;
    if (plan.settings.gvFromScene)
        in.sceneGeometry = [this, &frame] { return &sceneGeometryFor(frame); };
    return in;
}

void ForwardRenderer::Impl::releaseCulled() {
    for (const std::unique_ptr<FramePass>& pass : passes)
        pass->releaseIfCulled(graph);
    if (!plan.lpvRuns)
        lpv->disable(plan.lpvOffReason);
}

} // namespace lpv::renderer
