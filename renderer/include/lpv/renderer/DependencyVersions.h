#pragma once
// Versions of lpv_renderer's third-party libraries (see lpv/scene/DependencyVersions.h).
// The OpenGL driver is not among them: it depends on the context, see GlContext.h.
#include "lpv/scene/DependencyVersions.h"

#include <vector>

namespace lpv::renderer {

// libepoxy.
std::vector<scene::DependencyVersion> dependencyVersions();

} // namespace lpv::renderer
