#pragma once
// The visibility-aware lookup (docs/lpv.md, "Visibility-aware lookup"), CPU
// twin of shaders/lpv_visibility.comp and the visibility path of
// shaders/lpv_lookup.glsl. Per LPV cell and axis direction, the mean and mean
// square of the distance to the nearest surface, read from the geometry
// volume on the two cell faces ahead; at shading, each of the 8 trilinear taps
// is weighted by the Chebyshev bound on the chance that the shading point
// sees the tap's centre (as DDGI weights its probes), so a cell on the far
// side of a wall is not read.
#include "lpv/renderer/lpv/LpvReference.h"

#include <array>

namespace lpv::renderer::lpvref {

// LpvPass hands the same numbers to the GPU.
struct VisibilitySettings {
    float maxDistance = 2.0f;    // cells: the distance a direction without a surface records
    float closedCoverage = 0.5f; // surface coverage of a face at which it counts as closed for sight
    float normalBias = 0.5f;     // cells: the shading point moved along its normal before the test
    float minVariance = 1e-4f;   // cells^2: floor of the Chebyshev bound's variance
};

// Per cell (index as ShGrid) and axis a: (E[d], E[d^2]) along +a in xy and
// along -a in zw, in cells; the GPU stores the same vec4 per cell and axis.
struct MomentsGrid {
    int n = 0;
    std::vector<std::array<glm::vec4, 3>> moments;

    explicit MomentsGrid(int cells = 0);
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n) * (std::size_t(y) + std::size_t(n) * std::size_t(z));
    }
    const std::array<glm::vec4, 3>& at(int x, int y, int z) const { return moments[index(x, y, z)]; }
};

// The chance that a ray along axis `axis` through GV coordinate g is stopped:
// surfaces block sight from either side, unlike light (see the .cpp).
float faceOpacity(const GvGrid& gv, const glm::vec3& g, int axis, float closedCoverage);

// The moments of every cell of `gv`'s cascade.
MomentsGrid buildMoments(const GvGrid& gv, const VisibilitySettings& settings);

// The chance that a point at `offset` (cells) from a cell centre sees it: per
// axis the one-sided Chebyshev bound variance / (variance + (|o_a| - mean)^2)
// beyond the mean distance toward the point (1 before it), multiplied.
float chebyshevVisibility(const std::array<glm::vec4, 3>& moments, const glm::vec3& offset, float minVariance);

// irradianceAt with each trilinear tap's weight times its visibility from x
// moved by normalBias cells along n, renormalised; plain trilinear where
// every weight vanishes.
glm::vec3 irradianceVisibleAt(const ShGrid& accumulated, const MomentsGrid& moments, const GridFrame& grid,
                              const glm::vec3& x, const glm::vec3& n, const VisibilitySettings& settings);

} // namespace lpv::renderer::lpvref
