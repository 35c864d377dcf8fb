#include "passes/lpv/LpvStages.h"

#include "frame/FrameState.h"

namespace lpv::renderer {

EffectDecision LpvStageInputs::decision() const {
    return runs ? runsBecause(sun ? "the sun's RSM" : "local lights or emissive surfaces") : skippedBecause(offReason);
}

EffectDecision LpvStageInputs::off() const { return skippedBecause("the LPV does not run: " + offReason); }

void LpvStage::setup(graph::PassSpec& pass, FrameState& state) {
    if (stage_.resources)
        stage_.resources(state);
    stage_.declare(pass, state.lpv);
}

scene::Expected<void> LpvStage::execute(graph::PassContext&, FrameState& state) {
    stage_.run(state.lpv);
    return {};
}

std::vector<std::unique_ptr<LpvStage>> makeLpvStages() {
    std::vector<std::unique_ptr<LpvStage>> stages;
    for (const LpvStageDefinition* stage : {&lpvInjectionStage, &skyInjectionStage, &lpvNormalsStage,
                                            &geometryVolumeStage, &lpvPropagationStage, &lpvBouncesStage})
        stages.push_back(std::make_unique<LpvStage>(*stage));
    return stages;
}

} // namespace lpv::renderer
