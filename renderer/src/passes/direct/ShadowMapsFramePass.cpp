#include "passes/direct/ShadowMapsFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "graph/ContentHash.h"

namespace lpv::renderer {

void ShadowMapsFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    const FrameContext& frame = state.frame;
    state.graph.importResource(resources::ShadowMaps, [this] {
        const GLuint id = maps_.primaryMap();
        return graph::ImportedView{id, graph::queryTexture(id)};
    });
    pass.decision = runsBecause("direct light is shadowed");
    state.shadowMaps = &maps_; // shading samples them
    pass.writes = {resources::ShadowMaps};
    // What the maps are drawn from besides the cascades' matrices: a cascade
    // whose snapped matrix did not move keeps its layer (ShadowPass).
    graph::ContentHash content;
    content.add(state.sceneGeneration);
    addLights(content, frame.scene.lights);
    for (const char* key : {"shadow.mapSize", "shadow.cascades", "shadow.stabilize", "shadow.cascadeDraws",
                            "shadow.farCascadeInterval"})
        content.add(frame.params.get(key));
    // The sun's cascades follow the camera; stale far cascades
    // (shadow.farCascadeInterval) still have to be redrawn when it stops.
    // Spot and point maps do not depend on the camera: without a shadowed
    // sun, turning the camera keeps them.
    pass.inputsKey = selectShadowLights(frame.scene).sun >= 0
                         ? graph::ContentHash().add(state.cameraKey()).add(maps_.refreshKey()).value()
                         : content.value();
    // lpv.reuse = false (the benchmarks) draws every cascade every frame.
    layersKey_ = frame.params.getBool("lpv.reuse") ? content.value() : 0;
}

scene::Expected<void> ShadowMapsFramePass::execute(graph::PassContext& ctx, FrameState& state) {
    return maps_.render(ctx.frame, *state.sceneGpu, *state.materialGpu, layersKey_);
}

} // namespace lpv::renderer
