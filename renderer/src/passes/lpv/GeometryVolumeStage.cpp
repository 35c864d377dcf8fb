// geometryVolume: the surfels that block and reflect light in the LPV, from
// the RSM and last frame's camera G-buffer, or from the scene's own GV
// (LpvPass::geometryStage).
#include "frame/FrameResources.h"
#include "passes/lpv/LpvStages.h"

namespace lpv::renderer {

namespace {

void declare(graph::PassSpec& pass, const LpvStageInputs& in) {
    // Bounces reflect at the GV's surfels, so they need it even without occlusion.
    pass.decision = !in.runs                             ? in.off()
                    : in.settings.geometryVolumeRuns() ? runsBecause("lpv.occlusion or lpv.bounces > 1")
                                                       : skippedBecause("lpv.occlusion is off and one bounce");
    if (in.sun && !in.settings.gvFromScene)
        pass.reads = {resources::RsmPosition, resources::RsmNormal};
    if (in.cameraGv)
        pass.readsHistory = {resources::CameraDepth, resources::CameraNormal};
    pass.writes = {resources::LpvGeometry};
    pass.inputsKey = in.key;
}

void run(const LpvStageInputs& in) {
    in.lpv->geometryStage(in.rsm(), in.camera, in.sceneGeometry ? in.sceneGeometry() : nullptr);
}

} // namespace

const LpvStageDefinition geometryVolumeStage{scene::Pass::GeometryVolume, &declare, &run};

} // namespace lpv::renderer
