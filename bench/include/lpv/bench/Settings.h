#pragma once
// `--set KEY=V1,V2,...`: a list of values sweeps the key. Several swept keys
// give every combination. `lpv render` writes one image per combination, so
// settings can be compared side by side (e.g. lpv.propagationSteps=0,2,8).
#include "lpv/scene/ParameterRegistry.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lpv::bench {

using Setting = std::pair<std::string, std::string>; // key, value as text

struct SetPlan {
    std::vector<Setting> fixed;                   // KEY=VALUE given once
    std::vector<std::vector<Setting>> combinations; // one entry per image; {} when nothing is swept
};

// Splits "KEY=VALUE" arguments; `error` is set (and the plan empty) on a
// malformed one. Values are checked later against the registry.
SetPlan planSettings(const std::vector<std::string>& sets, std::string& error);

// Every value of every combination checked against the registry on top of
// `base` before anything renders; the first error's message, or nullopt.
// `option` names the flag in the message ("--set", "--sweep").
std::optional<std::string> checkCombinations(const SetPlan& plan, const scene::ParameterSet& base,
                                             const std::string& option);

// File-name suffix for one combination: "-lpv.propagationSteps-2" per setting.
std::string combinationSuffix(const std::vector<Setting>& combination);

} // namespace lpv::bench
