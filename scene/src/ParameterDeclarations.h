#pragma once
#include "lpv/scene/ParameterRegistry.h"

namespace lpv::scene {
std::vector<ParameterInfo> declareParameters();
}
