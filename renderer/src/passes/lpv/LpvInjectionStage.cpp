// lpvInjection: the VPLs of the sun's RSM, the local lights' RSM faces and
// the emissive surfaces into the LPV's volumes (LpvPass::injectStage).
#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

// The LPV's volumes are graph resources from here on.
void importVolumes(FrameState& state) {
    const LpvVolumes& volumes = state.lpv.lpv->volumes();
    // Three bands keep their steps in the interleaved volumes only (LpvVolumes::ensure).
    importTexture(state.graph, resources::LpvVolumes, [&volumes] {
        return volumes.bands() == 3 ? volumes.interleaved[0].id() : volumes.volume[0].channel[0].id();
    });
    importTexture(state.graph, resources::LpvAccumulator, [&volumes] { return volumes.accumulator.channel[0].id(); });
    importTexture(state.graph, resources::LpvGeometry, [&volumes] { return volumes.geometry.id(); });
    importTexture(state.graph, resources::LpvNormals, [&volumes] { return volumes.normals[0].id(); });
}

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    pass.decision = in.decision();
    if (in.sun)
        pass.reads = {resources::RsmPosition, resources::RsmNormal, resources::RsmFlux};
    if (in.local)
        pass.reads.insert(pass.reads.end(),
                          {resources::LocalRsmPosition, resources::LocalRsmNormal, resources::LocalRsmFlux});
    if (in.emissive)
        pass.reads.push_back(resources::EmissiveVpls);
    pass.writes = {resources::LpvVolumes, resources::LpvAccumulator};
    pass.inputsKey = in.key;
}

void run(const LpvStageInputs& in) {
    in.lpv->injectStage(in.rsm(), in.localInputs(), in.settings.directed);
}

} // namespace

const LpvStageDefinition lpvInjectionStage{scene::Pass::LpvInjection, &declare, &run, &importVolumes};

} // namespace lpv::renderer
