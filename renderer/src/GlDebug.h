#pragma once
// Whether GL debug output is wanted (debug builds, or LPV_GL_DEBUG=1): the
// platform context files ask for a debug context when it is.

namespace lpv::renderer {

bool glDebugOutputRequested();

} // namespace lpv::renderer
