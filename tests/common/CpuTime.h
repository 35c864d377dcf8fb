#pragma once
// CPU seconds, for tests that bound how much work a refusal does. A refusal
// must come before the work (a solve, a render, a hang in a loop); wall
// time tells that apart only on an idle machine: beside other builds, or at
// low priority, a process that does nothing waits for a core and fails a
// wall-clock bound (a fresh Debian 12 chroot at nice 19: 0.3 s refusals took
// 7 to 20 s). CPU time counts only what the code did.
#include <sys/resource.h>
#include <ctime>

namespace lpv::test {

// This process, all its threads.
inline double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The children this process has waited for (runLpv's popen/pclose does),
// user plus system: take it before and after a run.
inline double childrenCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    auto seconds = [](const timeval& v) { return double(v.tv_sec) + 1e-6 * double(v.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace lpv::test
