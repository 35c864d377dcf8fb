#include "lpv/renderer/lpv/LpvVisibility.h"

#include <algorithm>
#include <cmath>

namespace lpv::renderer::lpvref {

MomentsGrid::MomentsGrid(int cells) : n(cells) {
    moments.assign(std::size_t(cells) * std::size_t(cells) * std::size_t(cells), {});
}

float faceOpacity(const GvGrid& gv, const glm::vec3& g, int axis, float closedCoverage) {
    // B = sum of coverage * cosineLobe(n): the DC is the summed coverage, the
    // linear band the coverage-weighted normal. A one-sided surface stops a
    // ray along a with its projected coverage |L_a| from either side; what
    // cancels in L (both faces of a wall, a crumpled surface) has lost its
    // orientation and counts with the mean projection of a random
    // orientation, one half. The GV rounds a wall that ends on a GV plane to
    // half coverage there, so a face counts as closed from closedCoverage.
    const glm::vec4 b = gv.sample(g);
    const float coverage = b.x / sh::kCos0;
    const glm::vec3 l = glm::vec3(-b.w, -b.y, b.z) / sh::kCos1;
    const float projected = std::abs(l[axis]) + 0.5f * std::max(coverage - glm::length(l), 0.0f);
    return std::clamp(projected / closedCoverage, 0.0f, 1.0f);
}

MomentsGrid buildMoments(const GvGrid& gv, const VisibilitySettings& settings) {
    MomentsGrid out(gv.n);
    // The GV puts every surface on a GV plane, i.e. on an LPV cell face: along
    // an axis the nearest surface lies on the cell's own face (0.5 cells) or
    // the next (1.5 cells), or past both (maxDistance).
    constexpr float kFaces[2] = {0.5f, 1.5f};
    const float far = settings.maxDistance;
    for (int z = 0; z < gv.n; ++z)
        for (int y = 0; y < gv.n; ++y)
            for (int x = 0; x < gv.n; ++x) {
                const glm::vec3 centre = glm::vec3(x, y, z) + 0.5f; // an LPV cell centre in GV coordinates
                auto& cell = out.moments[out.index(x, y, z)];
                for (int a = 0; a < 3; ++a)
                    for (int side = 0; side < 2; ++side) {
                        glm::vec3 dir(0.0f);
                        dir[a] = side == 0 ? 1.0f : -1.0f;
                        float transmitted = 1.0f, mean = 0.0f, meanSquare = 0.0f;
                        for (float t : kFaces) {
                            const float hit = transmitted * faceOpacity(gv, centre + t * dir, a, settings.closedCoverage);
                            mean += hit * t;
                            meanSquare += hit * t * t;
                            transmitted -= hit;
                        }
                        mean += transmitted * far;
                        meanSquare += transmitted * far * far;
                        cell[std::size_t(a)][2 * side] = mean;
                        cell[std::size_t(a)][2 * side + 1] = meanSquare;
                    }
            }
    return out;
}

float chebyshevVisibility(const std::array<glm::vec4, 3>& moments, const glm::vec3& offset, float minVariance) {
    // Per axis, not one test along the offset with the three axes' moments
    // mixed by w_a^2 (an ambient cube standing in for DDGI's octahedral
    // texels): mixing blurs a wall's sharp distance with the open axes beside
    // it. On the thin-wall case (blocking x2) the wall's dark face read 29% of
    // its bright face with the mix, 7.8% per axis (docs/lpv.md).
    float visible = 1.0f;
    for (int a = 0; a < 3; ++a) {
        const glm::vec4& m = moments[std::size_t(a)];
        const float mean = offset[a] < 0.0f ? m.z : m.x;
        const float meanSquare = offset[a] < 0.0f ? m.w : m.y;
        const float d = std::abs(offset[a]);
        if (d <= mean)
            continue;
        const float variance = std::max(meanSquare - mean * mean, minVariance);
        visible *= variance / (variance + (d - mean) * (d - mean));
    }
    return visible;
}

glm::vec3 irradianceVisibleAt(const ShGrid& accumulated, const MomentsGrid& moments, const GridFrame& grid,
                              const glm::vec3& x, const glm::vec3& n, const VisibilitySettings& settings) {
    const glm::vec3 u = (x - grid.origin) / grid.cellSize;
    // Moved off the surface, as DDGI does, so the surface it lies on does not hide the cells in front of it.
    const glm::vec3 seen = u + n * settings.normalBias;
    // The taps of sampleTrilinear: texel centres at integer + 0.5, clamped to the grid.
    const glm::vec3 v = glm::clamp(u - 0.5f, glm::vec3(0.0f), glm::vec3(float(grid.n - 1)));
    const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(v)), glm::ivec3(grid.n - 1));
    const glm::ivec3 i1 = glm::min(i0 + 1, glm::ivec3(grid.n - 1));
    const glm::vec3 f = v - glm::vec3(i0);
    std::array<glm::vec4, 3> weighted{}, plain{};
    float weights = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c(o.x ? i1.x : i0.x, o.y ? i1.y : i0.y, o.z ? i1.z : i0.z);
        const float trilinear = (o.x ? f.x : 1.0f - f.x) * (o.y ? f.y : 1.0f - f.y) * (o.z ? f.z : 1.0f - f.z);
        const float w = trilinear * chebyshevVisibility(moments.at(c.x, c.y, c.z), seen - (glm::vec3(c) + 0.5f),
                                                        settings.minVariance);
        weights += w;
        for (int ch = 0; ch < 3; ++ch) {
            weighted[std::size_t(ch)] += w * accumulated.at(ch, c.x, c.y, c.z);
            plain[std::size_t(ch)] += trilinear * accumulated.at(ch, c.x, c.y, c.z);
        }
    }
    // Every tap hidden (a point inside a closed cell): the plain lookup rather than a division by zero.
    const bool anyVisible = weights > 1e-6f;
    glm::vec3 e(0.0f);
    for (int ch = 0; ch < 3; ++ch) {
        const glm::vec4 l = anyVisible ? weighted[std::size_t(ch)] / weights : plain[std::size_t(ch)];
        e[ch] = sh::irradiance(l, n) / (grid.cellSize * grid.cellSize);
    }
    return e;
}

} // namespace lpv::renderer::lpvref
