#include "RsmPass.h"

namespace lpv::renderer {

scene::Expected<RsmPass> RsmPass::create() { return RsmPass{}; }

scene::Expected<void> RsmPass::render(const FrameContext&, const SceneGpu&, const MaterialGpu&) { return {}; }

std::vector<DebugImage> RsmPass::debugImages() const { return {}; }

} // namespace lpv::renderer
