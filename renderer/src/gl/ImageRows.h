#pragma once
// GL reads images bottom row first; the renderer's read-backs and dumps give
// rows top to bottom.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace lpv::renderer {

template <class T>
void flipRows(std::vector<T>& pixels, int width, int height, int channels) {
    const std::size_t row = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         pixels.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row));
}

} // namespace lpv::renderer
