#pragma once
// The GPU LPV's accumulator (three colour channels of two-band SH, as
// LpvPass::readAccumulator gives them) against the CPU twin's grid.
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lpv::renderer {

// The largest |GPU - CPU| over every coefficient, relative to the largest
// |CPU| (absolute when the CPU grid is all zero); `largest` gets that
// largest |CPU|. A size mismatch fails the test.
inline double relativeDifference(const lpvref::ShGrid& expected, const std::array<std::vector<glm::vec4>, 3>& gpu,
                                 float* largest = nullptr) {
    float maxAbs = 0.0f, maxValue = 0.0f;
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(gpu[std::size_t(c)].size(), expected.channel[c].size());
        for (std::size_t i = 0; i < expected.channel[c].size() && i < gpu[std::size_t(c)].size(); ++i)
            for (int j = 0; j < 4; ++j) {
                maxAbs = std::max(maxAbs, std::abs(gpu[std::size_t(c)][i][j] - expected.channel[c][i][j]));
                maxValue = std::max(maxValue, std::abs(expected.channel[c][i][j]));
            }
    }
    if (largest)
        *largest = maxValue;
    return maxValue > 0.0f ? double(maxAbs / maxValue) : double(maxAbs);
}

} // namespace lpv::renderer
