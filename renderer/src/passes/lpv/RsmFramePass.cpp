#include "passes/lpv/RsmFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "gl/GpuMemoryLedger.h"
#include "graph/ContentHash.h"

namespace lpv::renderer {

void RsmFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    importTexture(state.graph, resources::RsmPosition, [this] { return rsm_.positionArray(); });
    importTexture(state.graph, resources::RsmNormal, [this] { return rsm_.normalArray(); });
    importTexture(state.graph, resources::RsmFlux, [this] { return rsm_.fluxArray(); });
    pass.decision = !state.lpv.runs ? state.lpv.off()
                    : state.lpv.sun ? runsBecause("the sun lights the scene")
                                    : skippedBecause("no directional light");
    pass.writes = {resources::RsmPosition, resources::RsmNormal, resources::RsmFlux};
    graph::ContentHash h;
    // The tiles follow the cascades (the camera's position, its view with lpv.viewShift).
    h.add(state.sceneGeneration).add(state.rsmCascades);
    addLights(h, state.frame.scene.lights);
    pass.inputsKey = h.value();
}

scene::Expected<void> RsmFramePass::execute(graph::PassContext& ctx, FrameState& state) {
    return rsm_.render(ctx.frame, *state.sceneGpu, *state.materialGpu, state.rsmCascades);
}

void RsmFramePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    ledger.addTexture(resources::RsmPosition.name(), rsm_.positionArray());
    ledger.addTexture(resources::RsmNormal.name(), rsm_.normalArray());
    ledger.addTexture(resources::RsmFlux.name(), rsm_.fluxArray());
    ledger.addTexture("rsm.depth", rsm_.depthArray());
}

} // namespace lpv::renderer
