#pragma once
// Image files in and out through OpenImageIO. Writes are atomic (temporary
// file beside the target, then rename) like every other save.
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace lpv::importers {

using Image8 = scene::Image8;

// Larger sides are refused before anything is allocated (a corrupt header
// must not cost gigabytes). The side is not the memory limit: every read
// also keeps within the budgets of ImageBudget.h (issue #42), checked from
// the file's header before OpenImageIO opens it, and whatever OpenImageIO
// throws comes back as an error value.
inline constexpr int kMaxImageSide = 16384;
// Named channels readImageChannels accepts (a path-traced reference has about a dozen).
inline constexpr int kMaxImageChannels = 64;

// Format from the extension (.png, .jpg, .bmp, .tga, .exr...).
scene::Expected<void> writeImage(const std::filesystem::path& file, const Image8& image);
// Floating-point pixels (rows top to bottom), for EXR and other HDR formats.
scene::Expected<void> writeImageFloat(const std::filesystem::path& file, int width, int height, int channels,
                                      const std::vector<float>& pixels);
// Any number of named float channels, interleaved per pixel (rows top to
// bottom): multi-layer EXR such as the path-traced reference ("R", "G", "B",
// "indirect.R", ...). String attributes travel in the file's header.
struct FloatChannels {
    int width = 0;
    int height = 0;
    std::vector<std::string> names;
    std::vector<float> pixels; // width * height * names.size()
    std::vector<std::pair<std::string, std::string>> attributes;
};
scene::Expected<void> writeImageChannels(const std::filesystem::path& file, const FloatChannels& image,
                                         const std::vector<std::pair<std::string, std::string>>& attributes = {});
scene::Expected<FloatChannels> readImageChannels(const std::filesystem::path& file);

scene::Expected<Image8> readImage8(const std::filesystem::path& file);

// Four channels for use as a texture: grey, grey + alpha and RGB are expanded
// (palettised BMPs already arrive expanded from OpenImageIO). `shrink` (a
// power of two) makes it that many times smaller on each side, box-filtered
// while it is decoded in strips, so the full-size image is never held.
scene::Expected<Image8> readTextureRgba8(const std::filesystem::path& file, int shrink = 1);

// 64x64 magenta and black checks: what a missing or unreadable texture looks like.
Image8 placeholderTexture();

struct LoadedTexture {
    Image8 image;            // RGBA8, rows top to bottom
    bool placeholder = false;
    std::string warning;     // names the file and why, when placeholder
};
// Never fails: a texture that cannot be read (or is over the budget) becomes
// the placeholder plus a warning. `shrink` as for readTextureRgba8.
LoadedTexture loadTextureOrPlaceholder(const std::filesystem::path& file, int shrink = 1);

} // namespace lpv::importers
