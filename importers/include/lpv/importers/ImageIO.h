#pragma once
// Image files in and out through OpenImageIO. Writes are atomic (temporary
// file beside the target, then rename) like every other save.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace lpv::importers {

struct Image8 {
    int width = 0;
    int height = 0;
    int channels = 4;
    std::vector<std::uint8_t> pixels; // rows top to bottom
};

// Format from the extension (.png, .jpg, .bmp, .tga, .exr...).
scene::Expected<void> writeImage(const std::filesystem::path& file, const Image8& image);
scene::Expected<Image8> readImage8(const std::filesystem::path& file);

} // namespace lpv::importers
