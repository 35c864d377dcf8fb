#pragma once
// Decoding a texture a strip of rows at a time, shrinking it while it is
// read: the peak is the output plus one strip, never the full image
// (issue #42: one 16384^2 PNG cost 3.6 GiB at `lpv render`).
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace lpv::importers {

// Subimage 0 of an opened file as RGBA8 (grey, grey + alpha and RGB
// expanded), `shrink` (a power of two) times smaller on each side, each
// output texel the mean of the shrink x shrink texels it covers (fewer at
// the right and bottom edges when the size does not divide). Throws what
// OpenImageIO throws; the caller catches at its boundary.
scene::Expected<scene::Image8> readRgba8InStrips(OIIO::ImageInput& in, const std::filesystem::path& file,
                                                 int shrink);

} // namespace lpv::importers
