// lpvNormals: directed propagation's normals volume, the VPL normals summed
// at injection averaged and dilated (LpvPass::normalsStage).
#include "frame/FrameResources.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    pass.decision = !in.runs              ? in.off()
                    : in.settings.directed ? runsBecause("directed propagation")
                                           : skippedBecause("lpv.directedPropagation is off");
    pass.reads = {resources::LpvVolumes}; // the VPL normals summed at injection
    pass.writes = {resources::LpvNormals};
    pass.inputsKey = in.key;
}

void run(const LpvStageInputs& in) { in.lpv->normalsStage(in.settings.directedDilation); }

} // namespace

const LpvStageDefinition lpvNormalsStage{scene::Pass::LpvNormals, &declare, &run};

} // namespace lpv::renderer
