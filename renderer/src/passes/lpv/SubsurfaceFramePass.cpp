#include "passes/lpv/SubsurfaceFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"

namespace lpv::renderer {

void SubsurfaceFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    importTexture(state.graph, resources::SubsurfaceAccumulator,
                  [this] { return gpu_ ? gpu_->accumulatorTexture() : 0u; });
    pass.decision = !state.lpv.runs ? state.lpv.off() : state.subsurface;
    pass.reads = {resources::RsmPosition, resources::RsmNormal, resources::RsmFlux, resources::LpvVolumes};
    pass.writes = {resources::SubsurfaceAccumulator};
    pass.inputsKey = state.lpv.key;
    // Shading adds the light that crossed translucent materials (frame/IndirectLight.h).
    if (pass.decision.runs()) {
        IndirectLight light;
        light.provider = id();
        light.lookup = IndirectLight::Lookup::SubsurfaceVolume;
        light.reads = {resources::SubsurfaceAccumulator};
        light.bind = [this](const CachedProgram& shader, graph::PassContext& ctx) {
            gpu_->bindForShading(shader, ctx.allocateUnit());
        };
        state.indirectLight.push_back(std::move(light));
    }
}

scene::Expected<void> SubsurfaceFramePass::execute(graph::PassContext& ctx, FrameState& state) {
    if (auto created = createOnFirstRun(gpu_, &LpvSubsurfacePass::create); !created)
        return created;
    gpu_->run(LpvSubsurfaceSettings::fromParameters(ctx.frame.params), *state.lpv.lpv, state.lpv.rsm());
    return {};
}

void SubsurfaceFramePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    if (gpu_)
        gpu_->addGpuMemory(ledger);
}

} // namespace lpv::renderer
