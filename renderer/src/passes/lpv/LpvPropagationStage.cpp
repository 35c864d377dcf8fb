// lpvPropagation: lpv.propagationSteps steps per cascade in the chosen
// variant, summed into the accumulators shading reads (LpvPass::propagationStage),
// which it declares as the frame's indirect light.
#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    pass.decision = in.decision();
    pass.reads = {resources::LpvVolumes, resources::LpvAccumulator};
    if (in.settings.geometryVolumeRuns())
        pass.reads.push_back(resources::LpvGeometry);
    if (in.settings.directed)
        pass.reads.push_back(resources::LpvNormals);
    pass.writes = {resources::LpvVolumes, resources::LpvAccumulator};
    pass.inputsKey = in.propagationKey;
}

void run(const LpvStageInputs& in) { in.lpv->propagationStage(in.settings); }

// Shading adds the accumulated light (frame/IndirectLight.h), from the
// volumes as this frame's run left them (visibility moments or not).
void declareIndirectLight(FrameState& state) {
    if (!state.lpv.runs)
        return;
    const LpvPass* lpv = state.lpv.lpv;
    IndirectLight light;
    light.provider = scene::Pass::LpvPropagation;
    light.lookup = IndirectLight::Lookup::LpvVolume;
    light.reads = {resources::LpvAccumulator};
    light.defines = [lpv](std::vector<std::string>& defines) {
        if (!lpv->visibilityBound())
            defines.push_back("LPV_NO_VISIBILITY 1");
        if (lpv->volumes().bands() == 3)
            defines.push_back("LPV_SH_BANDS 3"); // lpv_lookup.glsl adds band 2 (issue #47)
    };
    light.bind = [lpv](const CachedProgram& shader, graph::PassContext& ctx) {
        lpv->bindForShading(shader, ctx.frame.params, [&ctx] { return ctx.allocateUnit(); });
    };
    state.indirectLight.push_back(std::move(light));
}

} // namespace

const LpvStageDefinition lpvPropagationStage{scene::Pass::LpvPropagation, &declare, &run, &declareIndirectLight};

} // namespace lpv::renderer
