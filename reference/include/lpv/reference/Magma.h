#pragma once
// The 'magma' colour map (Smith and van der Walt, matplotlib 1.5, CC0), which
// the FLIP authors use for their error heat maps: black through purple and
// orange to pale yellow, perceptually uniform and readable in grey, so an
// error of 0.2 looks twice as far from black as one of 0.1.
#include "lpv/scene/Image.h"

#include <array>
#include <cstdint>
#include <vector>

namespace lpv::reference {

// 256 sRGB entries, 8 bits per channel; entry 0 is for 0, entry 255 for 1.
const std::array<std::array<std::uint8_t, 3>, 256>& magmaTable();
// The entry for `t` in [0, 1] (clamped; non-finite shows as 1: an error we cannot measure is not small).
std::array<std::uint8_t, 3> magma(float t);
// RGBA8 heat map of a `width` x `height` map of values in [0, 1] (rows top to bottom).
scene::Image8 magmaImage(const std::vector<float>& values, int width, int height);

} // namespace lpv::reference
