#pragma once
// `lpv render --dump rsm,shadow`: each internal image of the renderer is
// written twice beside the output, as EXR (the exact floats) and as PNG
// (scaled into 0..255 so it can be looked at).
#include "lpv/renderer/ForwardRenderer.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::cli {

// The PNG view of a debug image: normals as n*0.5+0.5, depth and positions
// stretched over their range (background excluded), flux and colours scaled
// by their maximum. Exposed for tests.
std::vector<std::uint8_t> debugImageToRgba8(const renderer::DebugImage& image);

// Writes <stem>-<name>.exr and .png beside `output`; returns the files written,
// or prints the error and returns nothing.
std::vector<std::filesystem::path> writeDebugImages(const std::vector<renderer::DebugImage>& images,
                                                    const std::filesystem::path& output, bool& ok);

} // namespace lpv::cli
