#include "lpv/bench/Machine.h"

#include "CpuModel.h"

#include <thread>

namespace lpv::bench {

std::string describeMachine(const std::string& glRenderer, const std::string& glVersion) {
    return cpuModel() + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores | " + glRenderer + " | " +
           glVersion;
}

} // namespace lpv::bench
