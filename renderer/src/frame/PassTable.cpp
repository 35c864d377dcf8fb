// The frame's passes, one line each, in the order they are declared (the
// graph orders them by what they read and write; among independent passes
// the earlier line runs first, and `lpv render --graph` lists them so).
// A pass in its own file (FramePass.h) joins the frame here with one line
// (and its include); its name and outputs come from its own header
// (PassList.h), so `--dump` learns them from this list too.
#include "frame/ForwardRendererImpl.h"
#include "frame/PassList.h"
#include "lpv/renderer/FrameGraphReport.h"

#include "passes/direct/DepthPrepassPass.h"
#include "passes/direct/ExposureFramePass.h"
#include "passes/direct/ShadingPass.h"
#include "passes/direct/ShadowMapsFramePass.h"
#include "passes/direct/SunRaysPass.h"
#include "passes/direct/TonemapPass.h"
#include "passes/lpv/EmissiveVplsFramePass.h"
#include "passes/lpv/LocalRsmFramePass.h"
#include "passes/lpv/LpvLookupPass.h"
#include "passes/lpv/LpvLookupResolvePass.h"
#include "passes/lpv/LpvStages.h"
#include "passes/lpv/RsmFramePass.h"
#include "passes/lpv/SkyHeightFramePass.h"
#include "passes/lpv/SubsurfaceFramePass.h"
#include "passes/radiosity/RadiosityIndirectPass.h"

#include <algorithm>

namespace lpv::renderer {

namespace {

// The LPV's six stages (LpvStages.h), in their order.
struct LpvStagePasses {
    static std::vector<std::unique_ptr<LpvStage>> create() { return makeLpvStages(); }
};

// One line per pass, as written:
// clang-format off
using FramePasses = PassList<
    ShadowMapsFramePass,
    RsmFramePass,
    LocalRsmFramePass,
    EmissiveVplsFramePass,
    SkyHeightFramePass,
    LpvStagePasses,
    SubsurfaceFramePass,
    DepthPrepassPass,
    RadiosityIndirectPass,
    LpvLookupPass,
    LpvLookupResolvePass,
    ShadingPass,
    SunRaysPass,
    ExposureFramePass,
    TonemapPass>;
// clang-format on

} // namespace

scene::Expected<void> ForwardRenderer::Impl::buildPassTable() {
    auto built = FramePasses::build(passes);
    // The typed views the renderer keeps for read-backs and counters.
    shadows = findPass<ShadowMapsFramePass>(passes);
    rsm = findPass<RsmFramePass>(passes);
    localRsm = findPass<LocalRsmFramePass>(passes);
    emissiveVpls = findPass<EmissiveVplsFramePass>(passes);
    skyHeight = findPass<SkyHeightFramePass>(passes);
    subsurface = findPass<SubsurfaceFramePass>(passes);
    shading = findPass<ShadingPass>(passes);
    exposure = findPass<ExposureFramePass>(passes);
    tonemap = findPass<TonemapPass>(passes);
    return built;
}

const std::vector<std::string>& frameGraphNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (graph::ResourceHandle r : resources::shared)
            all.push_back(r.str());
        FramePasses::addOutputs(all);
        // Registry passes without a node of their own (glossy reflections are
        // part of shading; radiosity's solve and the reference are not frame passes).
        for (scene::Pass p : scene::allPasses())
            if (p != scene::Pass::GlossyReflections && p != scene::Pass::Radiosity &&
                p != scene::Pass::Reference)
                all.push_back(scene::passName(p));
        FramePasses::addNames(all);
        std::vector<std::string> unique;
        for (std::string& name : all)
            if (std::find(unique.begin(), unique.end(), name) == unique.end())
                unique.push_back(std::move(name));
        return unique;
    }();
    return names;
}

} // namespace lpv::renderer
