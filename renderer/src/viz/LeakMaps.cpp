#include "lpv/renderer/viz/LeakMaps.h"

#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/renderer/lpv/Sh.h"

#include <algorithm>

namespace lpv::renderer::viz {

namespace {

lpvref::GvGrid toGvGrid(const std::vector<glm::vec4>& geometry, int gridSize) {
    lpvref::GvGrid gv(gridSize);
    if (geometry.size() == gv.potential.size())
        gv.potential = geometry;
    return gv;
}

ShVolume zeroVolume(int gridSize) {
    const std::size_t cells = std::size_t(gridSize) * std::size_t(gridSize) * std::size_t(gridSize);
    return {std::vector<glm::vec4>(cells, glm::vec4(0.0f)), std::vector<glm::vec4>(cells, glm::vec4(0.0f)),
            std::vector<glm::vec4>(cells, glm::vec4(0.0f))};
}

std::size_t cellIndex(const glm::ivec3& c, int n) {
    return std::size_t(c.x) + std::size_t(n) * (std::size_t(c.y) + std::size_t(n) * std::size_t(c.z));
}

} // namespace

ShVolume leakHeat(const ShVolume& volume, const std::vector<glm::vec4>& geometry, int gridSize,
                  bool occlusion, float threshold) {
    const int n = gridSize;
    ShVolume out = zeroVolume(n);
    const std::size_t cells = out[0].size();
    if (volume[0].size() != cells || volume[1].size() != cells || volume[2].size() != cells)
        return out;
    const lpvref::GvGrid gv = toGvGrid(geometry, n);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::ivec3 p(x, y, z);
                for (const lpvref::PropagationFace& f : lpvref::propagationFaces()) {
                    const glm::ivec3 q = p - f.travel;
                    if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(q, glm::ivec3(n))))
                        continue;
                    // The same face and transmittance as the propagation step (LpvReference.cpp).
                    const glm::vec3 face = glm::vec3(q) + 0.5f + 0.5f * glm::vec3(f.travel);
                    const float blocking = 1.0f - lpvref::transmittance(gv, face, f.direction);
                    if (blocking < threshold)
                        continue;
                    const float passed = occlusion ? 1.0f - blocking : 1.0f;
                    for (std::size_t c = 0; c < 3; ++c) {
                        const float intensity =
                            std::max(0.0f, sh::evaluate(volume[c][cellIndex(q, n)], f.direction));
                        out[c][cellIndex(p, n)].x += f.solidAngle * intensity * passed;
                    }
                }
            }
    return out;
}

ShVolume backsideLight(const ShVolume& volume, const std::vector<glm::vec4>& geometry,
                       const LpvGridFrame& frame, float threshold) {
    const int n = frame.gridSize;
    ShVolume out = zeroVolume(n);
    const std::size_t cells = out[0].size();
    if (volume[0].size() != cells || volume[1].size() != cells || volume[2].size() != cells)
        return out;
    const lpvref::GvGrid gv = toGvGrid(geometry, n);
    const float faceArea = frame.cellSize * frame.cellSize;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                // The GV at the cell centre; its band 1 points along the surfels' mean normal
                // (a cosine lobe around n has band 1 = kCos1 (-n.y, n.z, -n.x)).
                const glm::vec4 b = gv.sample(glm::vec3(x, y, z) + 0.5f);
                const glm::vec3 band1(-b.w, -b.y, b.z);
                if (glm::length(band1) < 1e-6f)
                    continue;
                const glm::vec3 normal = glm::normalize(band1);
                if (sh::evaluate(b, normal) < threshold)
                    continue;
                // The back side faces -normal; light reaching it travels along +normal.
                const std::size_t i = cellIndex({x, y, z}, n);
                for (std::size_t c = 0; c < 3; ++c)
                    out[c][i].x = sh::irradiance(volume[c][i], -normal) / faceArea;
            }
    return out;
}

} // namespace lpv::renderer::viz
