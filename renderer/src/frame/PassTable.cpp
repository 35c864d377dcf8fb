// The frame's passes, one line each, in the order they are declared (the
// graph orders them by what they read and write; among independent passes
// the earlier line runs first, and `lpv render --graph` lists them so).
// A pass in its own file (FramePass.h) joins the frame here with one line.
// The renderer keeps typed views of those it asks for read-backs.
#include "frame/ForwardRendererImpl.h"

#include "passes/direct/DepthPrepassPass.h"
#include "passes/direct/ExposureFramePass.h"
#include "passes/direct/ShadingPass.h"
#include "passes/direct/ShadowMapsFramePass.h"
#include "passes/direct/SunRaysPass.h"
#include "passes/direct/TonemapPass.h"
#include "passes/lpv/EmissiveVplsFramePass.h"
#include "passes/lpv/LocalRsmFramePass.h"
#include "passes/lpv/LpvLookupPass.h"
#include "passes/lpv/LpvStages.h"
#include "passes/lpv/RsmFramePass.h"
#include "passes/lpv/SkyHeightFramePass.h"
#include "passes/lpv/SubsurfaceFramePass.h"
#include "passes/radiosity/RadiosityIndirectPass.h"

namespace lpv::renderer {

namespace {

// Adds passes to the table and returns each, for the renderer to keep a
// typed view of; a pass that could not be created (a shader error) is
// remembered, and finish() returns the first such error.
class TableBuilder {
  public:
    explicit TableBuilder(std::vector<std::unique_ptr<FramePass>>& table) : table_(table) {}
    template <typename Pass> Pass* add(std::unique_ptr<Pass> pass) {
        Pass* added = pass.get();
        table_.push_back(std::move(pass));
        return added;
    }
    template <typename Pass> Pass* add(scene::Expected<std::unique_ptr<Pass>> created) {
        if (created)
            return add(std::move(*created));
        if (!error_)
            error_ = created.error();
        return nullptr;
    }
    scene::Expected<void> finish() const {
        if (error_)
            return std::unexpected(*error_);
        return {};
    }

  private:
    std::vector<std::unique_ptr<FramePass>>& table_;
    std::optional<scene::Error> error_;
};

} // namespace

scene::Expected<void> ForwardRenderer::Impl::buildPassTable() {
    TableBuilder table(passes);
    shadows = table.add(ShadowMapsFramePass::create());
    rsm = table.add(RsmFramePass::create());
    localRsm = table.add(std::make_unique<LocalRsmFramePass>());
    emissiveVpls = table.add(std::make_unique<EmissiveVplsFramePass>());
    skyHeight = table.add(std::make_unique<SkyHeightFramePass>());
    for (std::unique_ptr<LpvStage>& stage : makeLpvStages())
        table.add(std::move(stage));
    subsurface = table.add(std::make_unique<SubsurfaceFramePass>());
    table.add(DepthPrepassPass::create());
    table.add(std::make_unique<RadiosityIndirectPass>());
    table.add(std::make_unique<LpvLookupPass>());
    shading = table.add(ShadingPass::create());
    table.add(std::make_unique<SunRaysPass>());
    exposure = table.add(ExposureFramePass::create());
    tonemap = table.add(TonemapPass::create());
    return table.finish();
}

} // namespace lpv::renderer
