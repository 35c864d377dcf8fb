#include "passes/lpv/EmissiveVplsFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "gl/GpuMemoryLedger.h"
#include "graph/ContentHash.h"
#include "lpv/renderer/lpv/EmissiveVpls.h"

namespace lpv::renderer {

void EmissiveVplsFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    importTexture(state.graph, resources::EmissiveVpls, [this] { return vpls_ ? vpls_->input().position : 0u; });
    pass.decision = !state.lpv.runs ? state.lpv.off() : state.emissive;
    pass.writes = {resources::EmissiveVpls};
    pass.inputsKey = graph::ContentHash().add(state.sceneGeneration).value();
}

scene::Expected<void> EmissiveVplsFramePass::execute(graph::PassContext& ctx, FrameState&) {
    // Two VPLs per finest cell along an emitter, at most 256^2.
    vpls_.emplace();
    vpls_->upload(lpvref::sampleEmissiveVpls(ctx.frame.scene, float(ctx.frame.params.getFloat("lpv.cellSize")) * 0.5f,
                                             65536, ctx.frame.worldMagnitude()));
    return {};
}

void EmissiveVplsFramePass::addGpuMemory(GpuMemoryLedger& ledger) const {
    if (!vpls_)
        return;
    const LpvLocalInput vpls = vpls_->input();
    for (GLuint t : {vpls.position, vpls.normal, vpls.flux})
        ledger.addTexture(resources::EmissiveVpls.name(), t);
}

} // namespace lpv::renderer
