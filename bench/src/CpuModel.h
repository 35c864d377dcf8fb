#pragma once
// The CPU's model name for benchmark reports ("AMD EPYC 7B13"), or
// "unknown CPU". Platform file: CpuModel.cpp asks each OS its own way.
#include <string>

namespace lpv::bench {

std::string cpuModel();

} // namespace lpv::bench
