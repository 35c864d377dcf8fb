// lpvPropagation: lpv.propagationSteps steps per cascade in the chosen
// variant, summed into the accumulators shading reads (LpvPass::propagationStage).
#include "frame/FrameResources.h"
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

} // namespace

const LpvStageDefinition lpvPropagationStage{scene::Pass::LpvPropagation, &declare, &run};

} // namespace lpv::renderer
