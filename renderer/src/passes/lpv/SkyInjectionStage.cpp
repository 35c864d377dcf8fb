// skyInjection: the sky's light into the LPV, down every open column of the
// height map (LpvPass::skyStage; docs/lpv.md "Sky light").
#include "frame/FrameResources.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    pass.decision = !in.runs ? in.off() : in.sky;
    pass.reads = {resources::SkyHeight, resources::LpvVolumes, resources::LpvAccumulator};
    pass.writes = {resources::LpvVolumes, resources::LpvAccumulator};
    pass.inputsKey = in.skyKey;
}

void run(const LpvStageInputs& in) { in.lpv->skyStage(in.skyInput()); }

} // namespace

const LpvStageDefinition skyInjectionStage{scene::Pass::SkyInjection, &declare, &run};

} // namespace lpv::renderer
