#include "passes/direct/ExposureFramePass.h"

#include "frame/FrameResources.h"
#include "frame/FrameState.h"
#include "lpv/renderer/AutoExposure.h"
#include "lpv/renderer/DisplayMapping.h"

namespace lpv::renderer {

void ExposureFramePass::setup(graph::PassSpec& pass, FrameState& state) {
    const bool autoExposure = state.frame.params.getEnum("output.exposureMode") == "auto";
    if (!autoExposure)
        meter_.reset();
    state.graph.importResource(resources::Exposure, [this] {
        const GLuint id = meter_.exposureBuffer();
        return graph::ImportedView{id, graph::queryBuffer(id)};
    });
    pass.decision = autoExposure ? runsBecause("output.exposureMode is auto")
                                 : skippedBecause("output.exposureMode is manual");
    pass.reads = {resources::CameraHdr};
    pass.writes = {resources::Exposure};
}

scene::Expected<void> ExposureFramePass::execute(graph::PassContext& ctx, FrameState&) {
    const FrameContext& f = ctx.frame;
    const double blend = timeStep_ ? adaptationBlend(*timeStep_, f.params.getFloat("output.exposureAdaptation")) : 1.0;
    meter_.meter(ctx.id(resources::CameraHdr), f.width, f.height, meterTargetOf(f.params), float(blend));
    return {};
}

} // namespace lpv::renderer
