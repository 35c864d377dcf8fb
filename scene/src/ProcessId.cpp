// Platform file: the process id (POSIX getpid, Windows _getpid).
#include "lpv/scene/ProcessId.h"

#ifdef _WIN32
#include <process.h>
#else
#include <unistd.h>
#endif

namespace lpv::scene {

int processId() {
#ifdef _WIN32
    return _getpid();
#else
    return static_cast<int>(::getpid());
#endif
}

} // namespace lpv::scene
