#include "lpv/renderer/viz/TileImages.h"

#include "lpv/renderer/viz/SliceImage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lpv::renderer::viz {

namespace {

std::uint8_t toByte(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

} // namespace

scene::Image8 debugImageView(const DebugImage& image) {
    const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
    const int c = image.channels;
    scene::Image8 view{image.width, image.height, 4, std::vector<std::uint8_t>(n * 4, 255)};
    std::vector<std::uint8_t>& out = view.pixels;
    if (c <= 0 || image.pixels.size() != n * std::size_t(c))
        return view;
    auto value = [&](std::size_t i, int ch) {
        return ch < c ? image.pixels[i * std::size_t(c) + std::size_t(ch)] : 0.0f;
    };
    // Texels with no surface: depth 1 (cleared), or w == 0 in 4-channel targets.
    auto empty = [&](std::size_t i) {
        return c == 1 ? value(i, 0) >= 1.0f : (c == 4 && value(i, 3) == 0.0f);
    };

    const bool isNormal = image.name.ends_with("normal");
    const bool stretch = c == 1 || image.name.ends_with("position");
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
    return view;
}

scene::Image8 tileRow(const std::vector<DebugImage>& images, int maxTileSize) {
    constexpr int kGap = 4, kFont = 2, kLabel = 5 * kFont + 6;
    std::vector<scene::Image8> views;
    std::vector<int> scales; // shrink factor per tile
    int width = kGap, height = 0;
    for (const DebugImage& d : images) {
        views.push_back(debugImageView(d));
        const int largest = std::max(d.width, d.height);
        const int shrink = maxTileSize > 0 ? std::max(1, (largest + maxTileSize - 1) / maxTileSize) : 1;
        scales.push_back(shrink);
        const int w = std::max(d.width / shrink, textWidth(d.name, kFont));
        width += w + kGap;
        height = std::max(height, d.height / shrink);
    }
    scene::Image8 row{width, height + kLabel + kGap, 4, {}};
    row.pixels.assign(std::size_t(row.width) * std::size_t(row.height) * 4, 0);
    for (std::size_t i = 3; i < row.pixels.size(); i += 4)
        row.pixels[i] = 255;
    int left = kGap;
    for (std::size_t t = 0; t < views.size(); ++t) {
        const scene::Image8& v = views[t];
        const int s = scales[t], w = v.width / s, h = v.height / s;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::uint8_t* src =
                    &v.pixels[(std::size_t(y * s) * std::size_t(v.width) + std::size_t(x * s)) * 4];
                std::uint8_t* dst =
                    &row.pixels[(std::size_t(kGap + y) * std::size_t(row.width) + std::size_t(left + x)) * 4];
                std::copy_n(src, 4, dst);
            }
        drawText(row, left, kGap + h + 4, images[t].name, kFont, glm::vec3(0.85f));
        left += std::max(w, textWidth(images[t].name, kFont)) + kGap;
    }
    return row;
}

std::vector<DebugImage> imagesNamed(const std::vector<DebugImage>& images, const std::string& prefix) {
    std::vector<DebugImage> out;
    for (const DebugImage& d : images)
        if (d.name.starts_with(prefix))
            out.push_back(d);
    return out;
}

} // namespace lpv::renderer::viz
