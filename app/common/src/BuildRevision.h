#pragma once
// The git revision this build was made from (`git describe --always --dirty`),
// or "unknown". Defined in a file generated at build time (cmake/GitRevision.cmake).

namespace lpv::app {

const char* buildRevision();

} // namespace lpv::app
