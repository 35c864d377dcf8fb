#pragma once
// A linear image to look at (`lpv reference --preview`, the sweep's crops,
// the editor's live reference): x / (x + key) per channel, then gamma 2.2,
// with key = the mean luminance, so that a dark interior and a sunlit court
// both show and several images can share one exposure.
#include "lpv/scene/Image.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::reference {

// RGBA8 of the rectangle [x0, x0 + w) x [y0, y0 + h) of a `width`-wide image
// (rows top to bottom); non-finite and negative values show black.
scene::Image8 previewImage(const std::vector<glm::vec3>& pixels, int width, int x0, int y0, int w, int h,
                           float key);
// The mean luminance of `pixels` where `mask` > 0.5 (every pixel where the
// mask is shorter), at least 1e-6: a key for previewImage.
float meanLuminance(const std::vector<glm::vec3>& pixels, const std::vector<float>& mask);

} // namespace lpv::reference
