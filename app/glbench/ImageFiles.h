#pragma once
// Images without an image library (issue #45): binary PPM (P6, the display
// image, 8 bits) and PFM (the HDR image, 32-bit floats, bottom row first as
// the format wants), so lpv-gl-bench shows what it timed on a machine that
// has no OpenImageIO.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace lpv::glbench {

// `rgba` rows top to bottom, 4 bytes a pixel; the alpha is dropped.
scene::Expected<void> writePpm(const std::filesystem::path& file, int width, int height,
                               const std::vector<std::uint8_t>& rgba);
// `rgba` rows top to bottom, 4 floats a pixel; written as little-endian RGB.
scene::Expected<void> writePfm(const std::filesystem::path& file, int width, int height,
                               const std::vector<float>& rgba);

} // namespace lpv::glbench
