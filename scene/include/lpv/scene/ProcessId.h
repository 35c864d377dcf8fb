#pragma once
// The current process's id, for names of temporary files that must not
// collide with another process writing beside them. The one place that asks
// the operating system for it (scene/src/ProcessId.cpp; docs/portability.md).

namespace lpv::scene {

int processId();

} // namespace lpv::scene
