#pragma once
// What the last frame's graph report says of one pass, for the reuse tests.
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/ParameterRegistry.h"

#include <string>

namespace lpv::test {

// Culled when the frame did not declare the pass.
inline renderer::PassStatus status(const renderer::ForwardRenderer& r, scene::Pass p) {
    const auto* report = r.graphReport().find(scene::passName(p));
    return report ? report->status : renderer::PassStatus::Culled;
}

inline std::string reason(const renderer::ForwardRenderer& r, scene::Pass p) {
    const auto* report = r.graphReport().find(scene::passName(p));
    return report ? report->reason : "not in the graph";
}

} // namespace lpv::test
