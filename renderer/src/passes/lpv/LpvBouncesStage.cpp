// lpvBounces: bounces 2.. lpv.bounces, each re-injecting the last one's light
// at the geometry volume's surfels (LpvPass::bounceStage; docs/lpv.md).
#include "frame/FrameResources.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    pass.decision = !in.runs                   ? in.off()
                    : in.settings.bounces > 1 ? runsBecause("lpv.bounces = " + std::to_string(in.settings.bounces))
                                              : skippedBecause("lpv.bounces is 1");
    pass.reads = {resources::LpvVolumes, resources::LpvAccumulator, resources::LpvGeometry};
    pass.writes = {resources::LpvVolumes, resources::LpvAccumulator};
    pass.inputsKey = in.propagationKey;
}

void run(const LpvStageInputs& in) { in.lpv->bounceStage(in.settings); }

} // namespace

const LpvStageDefinition lpvBouncesStage{scene::Pass::LpvBounces, &declare, &run};

} // namespace lpv::renderer
