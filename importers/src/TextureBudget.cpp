#include "lpv/importers/TextureBudget.h"

#include <algorithm>
#include <queue>
#include <utility>

namespace lpv::importers {

std::uint64_t textureBytesWithMips(std::int64_t width, std::int64_t height) {
    const std::uint64_t level0 = std::uint64_t(std::max<std::int64_t>(width, 0)) *
                                 std::uint64_t(std::max<std::int64_t>(height, 0)) * 4;
    return level0 + level0 / 3;
}

std::vector<int> planTextureShrink(const std::vector<TextureFootprint>& textures, std::uint64_t budget) {
    std::vector<int> shrink(textures.size(), 1);
    auto cost = [&](std::size_t i) {
        const std::int64_t s = shrink[i];
        return textureBytesWithMips((textures[i].width + s - 1) / s, (textures[i].height + s - 1) / s) *
               std::uint64_t(std::max(textures[i].copies, 0));
    };
    std::uint64_t total = 0;
    // Largest cost first; among equals the lowest index (the greater negated index).
    std::priority_queue<std::pair<std::uint64_t, std::int64_t>> largest;
    for (std::size_t i = 0; i < textures.size(); ++i) {
        total += cost(i);
        largest.emplace(cost(i), -std::int64_t(i));
    }
    while (total > budget && !largest.empty()) {
        const std::size_t i = std::size_t(-largest.top().second);
        largest.pop();
        const std::uint64_t before = cost(i);
        if (before == 0 || (textures[i].width <= shrink[i] && textures[i].height <= shrink[i]))
            continue; // already 1x1: nothing left to take
        shrink[i] *= 2;
        total -= before - cost(i);
        largest.emplace(cost(i), -std::int64_t(i));
    }
    return shrink;
}

} // namespace lpv::importers
