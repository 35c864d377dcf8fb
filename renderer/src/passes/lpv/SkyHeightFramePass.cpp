#include "passes/lpv/SkyHeightFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "graph/ContentHash.h"

namespace lpv::renderer {

void SkyHeightFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    importTexture(state.graph, resources::SkyHeight, [this] { return input_ ? input_->depth : 0u; });
    pass.decision = !state.lpv.runs ? state.lpv.off() : state.lpv.sky;
    pass.writes = {resources::SkyHeight};
    // Drawn over the coarsest cascade: it follows the cascades, not the view.
    pass.inputsKey = graph::ContentHash().add(state.sceneGeneration).add(state.lpv.cascades).value();
}

scene::Expected<void> SkyHeightFramePass::execute(graph::PassContext& ctx, FrameState& state) {
    if (auto created = createOnFirstRun(gpu_, &SkyHeightPass::create); !created)
        return created;
    const std::vector<LpvCascade>& cascades = state.lpv.cascades;
    auto rendered = gpu_->render(ctx.frame, *state.sceneGpu, *state.materialGpu, cascades.back(),
                                 SkyHeightPass::resolutionFor(state.lpv.settings.gridSize, int(cascades.size())));
    if (!rendered)
        return std::unexpected(rendered.error());
    input_ = *rendered;
    return {};
}

} // namespace lpv::renderer
