#include "DebugDump.h"

#include "lpv/importers/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace lpv::cli {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) { return s.ends_with(suffix); }

std::uint8_t toByte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

} // namespace

std::vector<std::uint8_t> debugImageToRgba8(const renderer::DebugImage& image) {
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    const int c = image.channels;
    std::vector<std::uint8_t> out(n * 4, 255);
    if (c <= 0 || image.pixels.size() != n * std::size_t(c))
        return out;
    auto value = [&](std::size_t i, int ch) { return ch < c ? image.pixels[i * std::size_t(c) + std::size_t(ch)] : 0.0f; };
    // Texels with no surface: depth 1 (cleared), or w == 0 in 4-channel targets.
    auto empty = [&](std::size_t i) { return c == 1 ? value(i, 0) >= 1.0f : (c == 4 && value(i, 3) == 0.0f); };

    const bool isNormal = endsWith(image.name, "normal");
    const bool stretch = c == 1 || endsWith(image.name, "position");
    float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                   std::numeric_limits<float>::max()};
    float hi[3] = {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
                   std::numeric_limits<float>::lowest()};
    float maxAll = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        if (empty(i))
            continue;
        for (int ch = 0; ch < std::min(c, 3); ++ch) {
            const float v = value(i, ch);
            if (!std::isfinite(v))
                continue;
            lo[ch] = std::min(lo[ch], v);
            hi[ch] = std::max(hi[ch], v);
            maxAll = std::max(maxAll, v);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        std::uint8_t* px = &out[i * 4];
        if (empty(i)) {
            px[0] = px[1] = px[2] = 0;
            continue;
        }
        for (int ch = 0; ch < 3; ++ch) {
            const int src = c == 1 ? 0 : ch;
            const float v = value(i, src);
            float mapped = 0.0f;
            if (isNormal)
                mapped = v * 0.5f + 0.5f;
            else if (stretch)
                mapped = hi[src] > lo[src] ? (v - lo[src]) / (hi[src] - lo[src]) : 0.5f;
            else
                mapped = maxAll > 0.0f ? v / maxAll : 0.0f;
            px[ch] = toByte(mapped);
        }
    }
    return out;
}

std::vector<std::filesystem::path> writeDebugImages(const std::vector<renderer::DebugImage>& images,
                                                    const std::filesystem::path& output, bool& ok) {
    ok = true;
    std::vector<std::filesystem::path> written;
    for (const renderer::DebugImage& image : images) {
        std::filesystem::path base = output;
        base.replace_filename(output.stem().string() + "-" + image.name);
        const std::filesystem::path exr = base.string() + ".exr", png = base.string() + ".png";
        if (auto r = importers::writeImageFloat(exr, image.width, image.height, image.channels, image.pixels); !r) {
            std::cerr << "lpv: " << r.error().describe() << "\n";
            ok = false;
            return written;
        }
        written.push_back(exr);
        if (auto r = importers::writeImage(png, {image.width, image.height, 4, debugImageToRgba8(image)}); !r) {
            std::cerr << "lpv: " << r.error().describe() << "\n";
            ok = false;
            return written;
        }
        written.push_back(png);
    }
    return written;
}

} // namespace lpv::cli
