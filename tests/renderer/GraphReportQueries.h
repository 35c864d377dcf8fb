#pragma once
// What the last frame's graph report says of one pass, for the reuse tests'
// fixtures to inherit.
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/ParameterRegistry.h"

#include <string>

namespace lpv::test {

struct GraphReportQueries {
    // Culled when the frame did not declare the pass.
    static renderer::PassStatus status(const renderer::ForwardRenderer& r, scene::Pass p) {
        const auto* report = r.graphReport().find(scene::passName(p));
        return report ? report->status : renderer::PassStatus::Culled;
    }
    static std::string reason(const renderer::ForwardRenderer& r, scene::Pass p) {
        const auto* report = r.graphReport().find(scene::passName(p));
        return report ? report->reason : "not in the graph";
    }
};

} // namespace lpv::test
