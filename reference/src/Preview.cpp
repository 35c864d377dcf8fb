#include "lpv/reference/Preview.h"

#include "lpv/reference/Metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lpv::reference {

scene::Image8 previewImage(const std::vector<glm::vec3>& pixels, int width, int x0, int y0, int w, int h,
                           float key) {
    scene::Image8 out{w, h, 4, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(h) * 4, 255)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 c = pixels[std::size_t(y0 + y) * std::size_t(width) + std::size_t(x0 + x)];
            for (int k = 0; k < 3; ++k) {
                const float v = std::isfinite(c[k]) ? std::max(c[k], 0.0f) : 0.0f;
                const float mapped = std::pow(v / (v + key), 1.0f / 2.2f);
                out.pixels[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(k)] =
                    std::uint8_t(std::lround(255.0f * mapped));
            }
        }
    return out;
}

float meanLuminance(const std::vector<glm::vec3>& pixels, const std::vector<float>& mask) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i)
        if (i >= mask.size() || mask[i] > 0.5f) {
            sum += luminance(pixels[i]);
            ++n;
        }
    return float(std::max(n ? sum / double(n) : 0.0, 1e-6));
}

} // namespace lpv::reference
