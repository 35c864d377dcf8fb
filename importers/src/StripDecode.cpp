#include "StripDecode.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

// Rows decoded per call for scanline files: 4 MiB at 16384 RGBA texels a
// row, and few enough calls that OpenImageIO's per-call cost does not show.
constexpr int kStripRows = 64;

// One texel of a c-channel row as RGBA.
void expand(const std::uint8_t* src, int c, std::uint8_t out[4]) {
    out[0] = src[0];
    out[1] = c >= 3 ? src[1] : src[0];
    out[2] = c >= 3 ? src[2] : src[0];
    out[3] = c == 2 ? src[1] : c == 4 ? src[3] : 255;
}

} // namespace

scene::Expected<scene::Image8> readRgba8InStrips(OIIO::ImageInput& in, const std::filesystem::path& file,
                                                 int shrink) {
    const OIIO::ImageSpec spec = in.spec();
    const int w = spec.width, h = spec.height, c = spec.nchannels;
    if (w <= 0 || h <= 0 || c < 1 || c > 4)
        return makeError(ErrorCode::OutOfRange, file.string(), "header",
                         "a texture has 1 to 4 channels; this image has " + std::to_string(c));
    shrink = std::max(shrink, 1);
    scene::Image8 out;
    out.width = (w + shrink - 1) / shrink;
    out.height = (h + shrink - 1) / shrink;
    out.channels = 4;
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * 4);

    // Tiled files are read a row of tiles at a time (read_tiles wants whole tiles).
    const bool tiled = spec.tile_width > 0;
    const int stripRows = tiled ? std::max(spec.tile_height, 1) : kStripRows;
    const std::size_t row = std::size_t(w) * std::size_t(c);
    std::vector<std::uint8_t> strip(row * std::size_t(stripRows));
    std::vector<std::uint64_t> sum(std::size_t(out.width) * 4, 0);

    for (int y0 = 0; y0 < h; y0 += stripRows) {
        const int y1 = std::min(y0 + stripRows, h);
        const bool ok = tiled ? in.read_tiles(0, 0, spec.x, spec.x + w, spec.y + y0, spec.y + y1, spec.z,
                                              spec.z + 1, 0, c, OIIO::TypeDesc::UINT8, strip.data())
                              : in.read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, c,
                                                  OIIO::TypeDesc::UINT8, strip.data());
        if (!ok)
            return makeError(ErrorCode::CorruptAsset, file.string(), "row " + std::to_string(y0),
                             "could not decode: " + in.geterror());
        for (int y = y0; y < y1; ++y) {
            const std::uint8_t* src = &strip[std::size_t(y - y0) * row];
            for (int x = 0; x < w; ++x) {
                std::uint8_t texel[4];
                expand(src + std::size_t(x) * std::size_t(c), c, texel);
                std::uint64_t* s = &sum[std::size_t(x / shrink) * 4];
                for (int k = 0; k < 4; ++k)
                    s[k] += texel[k];
            }
            // The last input row of an output row: divide by the texels each box held.
            if ((y + 1) % shrink != 0 && y + 1 != h)
                continue;
            const int oy = y / shrink;
            const std::uint64_t rows = std::uint64_t(y - oy * shrink + 1);
            std::uint8_t* dst = &out.pixels[std::size_t(oy) * std::size_t(out.width) * 4];
            for (int ox = 0; ox < out.width; ++ox) {
                const std::uint64_t n = rows * std::uint64_t(std::min(shrink, w - ox * shrink));
                for (int k = 0; k < 4; ++k) {
                    std::uint64_t& s = sum[std::size_t(ox) * 4 + std::size_t(k)];
                    dst[std::size_t(ox) * 4 + std::size_t(k)] = std::uint8_t((s + n / 2) / n);
                    s = 0;
                }
            }
        }
    }
    return out;
}

} // namespace lpv::importers
