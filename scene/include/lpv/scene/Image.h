#pragma once
// Decoded images as plain data: importers decode files into them, the
// renderer uploads them. Neither side needs the other.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace lpv::scene {

struct Image8 {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<std::uint8_t> pixels; // rows top to bottom
};

// The decoded texture of each material texture path (as written in
// Material, relative to the project file). A path absent here is drawn as
// if the material had no such texture.
using TextureImages = std::map<std::string, Image8>;

// Images derived from a file for one use are stored under the path plus a
// suffix, because the same file may also be used plainly elsewhere:
// a colour-keyed diffuse map (the key colour made transparent, 4ds COLOR_KEY)
inline constexpr const char* kColorKeySuffix = "#colorkey";
// and the tangent-space normal map made from a height (bump) map.
inline constexpr const char* kHeightNormalSuffix = "#height-normal";

} // namespace lpv::scene
