#pragma once
// What an image may cost before anything decodes it (issue #42). A header can
// claim any canvas; a library that believes it allocates the canvas before
// reading a pixel (OpenImageIO's GIF reader does so inside open(), and
// libjpeg's progressive decoder inside jpeg_start_decompress()). So the claim
// is read from the file's first bytes by our own code and weighed against
// two budgets before any library sees the file. docs/importers.md states the
// figures and why.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace lpv::importers {

// No decode may produce more than this (a 16384x16384 RGBA8 image, exactly),
// counted in what the decoder allocates and again in what our reader allocates.
inline constexpr std::uint64_t kMaxDecodedImageBytes = std::uint64_t(1) << 30;

// Above this many stored bytes, the claim must also be plausible for the
// file's size: compression can only expand so far (deflate at most 1032:1).
// Below it a lie costs too little memory to matter.
inline constexpr std::uint64_t kRatioCheckFromBytes = std::uint64_t(64) << 20;

// How far each kind of compression can expand, with some slack. A header
// whose stored samples exceed the file's size times this cannot be true.
inline constexpr double kUncompressedMaxRatio = 1.0;
inline constexpr double kExrRleMaxRatio = 64.0;    // a 2-byte run code covers at most 128 bytes
inline constexpr double kDeflateMaxRatio = 1100.0; // deflate's 1032:1, also JPEG's and PIZ's bounds
inline constexpr double kPxr24MaxRatio = 1400.0;   // deflate after 32-bit floats become 24 bits
inline constexpr double kLzwMaxRatio = 2600.0;     // 12-bit codes of up to ~3840 bytes: 2557:1
inline constexpr double kDwaMaxRatio = 33000.0;    // a flat 8x8 block (128 bytes) in 4 bytes, then deflate

// What a file's header claims, read without decoding.
struct ImageHeader {
    std::string format;      // "gif", "png", "jpeg", "bmp", "tga", "openexr", or OpenImageIO's name
    std::string compression; // as the budget weighs it: "none", "deflate", "rle", "lzw", "zip", ...
    std::int64_t width = 0;
    std::int64_t height = 0;
    std::int64_t depth = 1;         // slices of a volume image; we only read flat ones
    int channels = 0;               // what decoding yields (palettes expanded)
    int bytesPerSample = 1;         // of what decoding yields
    std::uint64_t storedBytes = 0;  // the samples as the file stores them, before compression
    std::uint64_t decodedBytes = 0; // what the decoder allocates to decode it (canvas, coefficients)
    double maxRatio = kDeflateMaxRatio;
};

// The file's claim, from our own reading of the header for GIF, PNG, JPEG,
// BMP, TGA and OpenEXR (before any library opens the file), else from
// OpenImageIO's header reader (exceptions caught), then weighed against the
// budgets: an error names the file, "header", the claim and the budget.
// Never decodes pixels.
scene::Expected<ImageHeader> readImageHeader(const std::filesystem::path& file);

// The budget rule alone (readImageHeader applies it): sides within
// kMaxImageSide, decodedBytes within kMaxDecodedImageBytes, and above
// kRatioCheckFromBytes, storedBytes within maxRatio times `fileBytes`.
scene::Expected<void> checkImageBudget(const std::filesystem::path& file, const ImageHeader& header,
                                       std::uint64_t fileBytes);

} // namespace lpv::importers
