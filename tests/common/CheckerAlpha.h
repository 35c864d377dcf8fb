#pragma once
// An 8x8 RGBA image whose alpha is a checker of 2x2-texel cells (a = 0 or
// 255, grey = alpha): the cut-out leaf of the masked-material tests, where
// half of a quad lets light and view through in a known pattern.
#include "lpv/scene/Image.h"

#include <cstdint>

namespace lpv::test {

inline scene::Image8 checkerAlpha() {
    scene::Image8 checker{8, 8, 4, {}};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t a = ((x / 2 + y / 2) % 2) ? 255 : 0;
            checker.pixels.insert(checker.pixels.end(), {a, a, a, 255});
        }
    return checker;
}

} // namespace lpv::test
