// The frame's passes, one line each, in the order they are declared (the
// graph orders them by what they read and write; among independent passes
// the earlier line runs first, and `lpv render --graph` lists them so).
// A pass in its own file (FramePass.h) joins the frame here with one line.
// The rest are still declared by the renderer (FramePasses.cpp,
// IndirectPasses.cpp) and take their place through declaredByRenderer.
#include "frame/ForwardRendererImpl.h"

#include "passes/direct/DepthPrepassPass.h"
#include "passes/direct/ExposureFramePass.h"
#include "passes/direct/ShadowMapsFramePass.h"
#include "passes/direct/SunRaysPass.h"
#include "passes/direct/TonemapPass.h"
#include "passes/lpv/EmissiveVplsFramePass.h"
#include "passes/lpv/LocalRsmFramePass.h"
#include "passes/lpv/LpvStages.h"
#include "passes/lpv/RsmFramePass.h"
#include "passes/lpv/SkyHeightFramePass.h"
#include "passes/lpv/SubsurfaceFramePass.h"
#include "passes/radiosity/RadiosityIndirectPass.h"

namespace lpv::renderer {

namespace {

// A group of passes the renderer still declares itself.
class DeclaredByRenderer final : public FramePass {
  public:
    explicit DeclaredByRenderer(std::function<void(FrameState&)> declare) : declare_(std::move(declare)) {}
    void addTo(FrameState& state) override { declare_(state); }

  private:
    std::function<void(FrameState&)> declare_;
};

// Adds `pass` to the table and returns it, for the renderer to keep a typed view of.
template <typename Pass> Pass& add(std::vector<std::unique_ptr<FramePass>>& table, std::unique_ptr<Pass> pass) {
    Pass& added = *pass;
    table.push_back(std::move(pass));
    return added;
}

std::unique_ptr<FramePass> declaredByRenderer(std::function<void(FrameState&)> declare) {
    return std::make_unique<DeclaredByRenderer>(std::move(declare));
}

} // namespace

scene::Expected<void> ForwardRenderer::Impl::buildPassTable() {
    auto shadowMaps = ShadowMapsFramePass::create();
    if (!shadowMaps)
        return std::unexpected(shadowMaps.error());
    shadows = &add(passes, std::move(*shadowMaps));
    auto sunRsm = RsmFramePass::create();
    if (!sunRsm)
        return std::unexpected(sunRsm.error());
    rsm = &add(passes, std::move(*sunRsm));
    localRsm = &add(passes, std::make_unique<LocalRsmFramePass>());
    emissiveVpls = &add(passes, std::make_unique<EmissiveVplsFramePass>());
    skyHeight = &add(passes, std::make_unique<SkyHeightFramePass>());
    for (std::unique_ptr<LpvStage>& stage : makeLpvStages())
        passes.push_back(std::move(stage));
    subsurface = &add(passes, std::make_unique<SubsurfaceFramePass>());
    auto depthPrepass = DepthPrepassPass::create();
    if (!depthPrepass)
        return std::unexpected(depthPrepass.error());
    passes.push_back(std::move(*depthPrepass));
    passes.push_back(std::make_unique<RadiosityIndirectPass>());
    passes.push_back(declaredByRenderer([this](FrameState& s) { declareShading(s); }));
    passes.push_back(std::make_unique<SunRaysPass>());
    auto meter = ExposureFramePass::create();
    if (!meter)
        return std::unexpected(meter.error());
    exposure = &add(passes, std::move(*meter));
    auto display = TonemapPass::create();
    if (!display)
        return std::unexpected(display.error());
    tonemap = &add(passes, std::move(*display));
    return {};
}

} // namespace lpv::renderer
