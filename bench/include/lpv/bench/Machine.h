#pragma once
// The machine a benchmark ran on, as every bench file heads its figures:
// "CPU model, N cores | GL renderer | GL version".
#include <string>

namespace lpv::bench {

std::string describeMachine(const std::string& glRenderer, const std::string& glVersion);

} // namespace lpv::bench
