#include "passes/lpv/LocalRsmFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "graph/ContentHash.h"

namespace lpv::renderer {

void LocalRsmFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    importTexture(state.graph, resources::LocalRsmPosition, [this] { return gpu_ ? gpu_->positionArray() : 0u; });
    importTexture(state.graph, resources::LocalRsmNormal, [this] { return gpu_ ? gpu_->normalArray() : 0u; });
    importTexture(state.graph, resources::LocalRsmFlux, [this] { return gpu_ ? gpu_->fluxArray() : 0u; });
    pass.decision = !state.lpv.runs ? state.lpv.off() : state.localLights;
    pass.writes = {resources::LocalRsmPosition, resources::LocalRsmNormal, resources::LocalRsmFlux};
    graph::ContentHash h;
    h.add(state.sceneGeneration);
    addLights(h, state.frame.scene.lights);
    pass.inputsKey = h.value();
}

scene::Expected<void> LocalRsmFramePass::execute(graph::PassContext& ctx, FrameState& state) {
    if (auto created = createOnFirstRun(gpu_, &LocalRsmPass::create); !created)
        return created;
    return gpu_->render(ctx.frame, *state.sceneGpu, *state.materialGpu, ctx.frame.params.getInt("lpv.localRsmSize"));
}

} // namespace lpv::renderer
