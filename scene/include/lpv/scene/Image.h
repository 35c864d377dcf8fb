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

} // namespace lpv::scene
