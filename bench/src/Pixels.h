#pragma once
// The renderer's RGBA float read-backs as RGB pixels (the metrics' input).
#include <glm/glm.hpp>

#include <vector>

namespace lpv::bench {

inline std::vector<glm::vec3> rgbOf(const std::vector<float>& rgba) {
    std::vector<glm::vec3> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
    return out;
}

} // namespace lpv::bench
