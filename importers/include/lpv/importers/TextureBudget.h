#pragma once
// The texture memory a scene may take (issue #42): every image the renderer
// uploads is RGBA8 with a full mip chain, and a scene's textures together
// stay within kSceneTextureBudgetBytes. Over the budget, the largest textures
// are halved first, on load, until the scene fits (loadSceneTextures warns
// for each, naming the file, its size and the size used).
#include <cstdint>
#include <vector>

namespace lpv::importers {

// 1 GiB of RGBA8 with mipmaps: a 16384x8192 texture, or sixteen 4096x4096
// ones, at full size. The renderer uploads each image with its mips; on a
// CPU machine (llvmpipe) those live in host memory beside our decoded copy,
// so the budget bounds a scene's textures at about twice this in RAM.
inline constexpr std::uint64_t kSceneTextureBudgetBytes = std::uint64_t(1) << 30;

// Bytes of one RGBA8 image of w x h with its full mip chain (4/3 of level 0).
std::uint64_t textureBytesWithMips(std::int64_t width, std::int64_t height);

struct TextureFootprint {
    std::int64_t width = 0; // as the file stores it
    std::int64_t height = 0;
    int copies = 1; // images made from the file (plain, colour-keyed, normals from heights)
};

// The power-of-two shrink of each texture (1: full size) that brings the
// total within `budget`: the texture that costs most is halved first, ties
// go to the earlier one, so the plan depends only on the sizes and order.
std::vector<int> planTextureShrink(const std::vector<TextureFootprint>& textures,
                                   std::uint64_t budget = kSceneTextureBudgetBytes);

} // namespace lpv::importers
