#pragma once
// The thin-wall hard case (docs/hard-cases.md) shared by the CPU and GL
// tests: two rooms split by a two-sided wall one cell thick at most, and the
// leak as the lookup at shading reads it.
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace lpv::renderer::thinwall {

struct RoomTexel {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 flux;
};

// Two rooms of `grid` split by a two-sided wall at x = wallCells * cell,
// floor to ceiling: the floor of the left room is sunlit (VPLs facing up,
// total flux 1 W), the right room's floor is dark. Every texel is also a GV
// surfel, as RsmPass writes them; the wall's surfels come 2 per cell along
// each axis on both faces, so the wall is closed.
inline std::vector<RoomTexel> twoRooms(const lpvref::GridFrame& grid, float wallCells) {
    const float cell = grid.cellSize;
    const float extent = cell * float(grid.n);
    const float wallX = wallCells * cell;
    std::vector<RoomTexel> texels;
    const int side = grid.n * 2;
    const float step = extent / float(side);
    int lit = 0;
    for (int i = 0; i < side; ++i)
        for (int k = 0; k < side; ++k) {
            const glm::vec3 p((float(i) + 0.5f) * step, 0.02f, (float(k) + 0.5f) * step);
            if (std::abs(p.x - wallX) < 0.5f * step)
                continue;
            const bool bright = p.x < wallX;
            lit += bright ? 1 : 0;
            texels.push_back({p, glm::vec3(0, 1, 0), glm::vec3(bright ? 1.0f : 0.0f)});
        }
    for (RoomTexel& t : texels)
        t.flux /= float(lit);
    for (int j = 0; j < side; ++j)
        for (int k = 0; k < side; ++k)
            for (float face : {-1.0f, 1.0f}) {
                const glm::vec3 p(wallX + 0.005f * face, (float(j) + 0.5f) * step, (float(k) + 0.5f) * step);
                texels.push_back({p, glm::vec3(face, 0, 0), glm::vec3(0.0f)});
            }
    return texels;
}

// Surfel area of a texel: a wall facing +-x seen by a sun overhead gets
// texelArea / 0.2 (LpvPass clamps the 1/cos); 2 surfels per cell and axis
// must cover (cell / 2)^2 each for the wall to be closed.
inline float texelArea(const lpvref::GridFrame& grid) { return 0.2f * (grid.cellSize * 0.5f) * (grid.cellSize * 0.5f); }

// The CPU reference's inputs: VPLs (lit texels) and GV surfels (all).
inline std::vector<lpvref::Vpl> vplsOf(const std::vector<RoomTexel>& texels) {
    std::vector<lpvref::Vpl> out;
    for (const RoomTexel& t : texels)
        if (t.flux.x > 0.0f)
            out.push_back({t.position, t.normal, t.flux});
    return out;
}
inline std::vector<lpvref::Surfel> surfelsOf(const std::vector<RoomTexel>& texels, float area) {
    std::vector<lpvref::Surfel> out;
    for (const RoomTexel& t : texels)
        out.push_back({t.position, t.normal, area / std::max(t.normal.y, 0.2f)}); // sun overhead
    return out;
}

// Shading points of the leak measure: the floor (y = 0, normal +y) on a
// 128 x 32 lattice over x and z, and both faces of the wall (5 mm off it,
// normals -x and +x) on 32 x 32 over y and z.
struct ShadingPoint {
    glm::vec3 position, normal;
    bool dark;  // in the dark room
    bool floor; // on the floor (else on the wall)
};
inline std::vector<ShadingPoint> shadingPoints(const lpvref::GridFrame& grid, float wallCells) {
    const float extent = grid.cellSize * float(grid.n);
    const float wallX = wallCells * grid.cellSize;
    std::vector<ShadingPoint> points;
    for (int i = 0; i < 128; ++i)
        for (int k = 0; k < 32; ++k) {
            const glm::vec3 x((float(i) + 0.5f) / 128.0f * extent, 0.0f, (float(k) + 0.5f) / 32.0f * extent);
            if (std::abs(x.x - wallX) > 1e-3f)
                points.push_back({x, glm::vec3(0, 1, 0), x.x > wallX, true});
        }
    for (int j = 0; j < 32; ++j)
        for (int k = 0; k < 32; ++k) {
            const float y = (float(j) + 0.5f) / 32.0f * extent, z = (float(k) + 0.5f) / 32.0f * extent;
            points.push_back({glm::vec3(wallX - 0.005f, y, z), glm::vec3(-1, 0, 0), false, false});
            points.push_back({glm::vec3(wallX + 0.005f, y, z), glm::vec3(1, 0, 0), true, false});
        }
    return points;
}

// The leak as shading reads it: the mean irradiance (red) on the dark
// room's floor over the mean on the bright room's floor, and the same for
// the wall's dark face over its bright face. `irradiance` is indexed like
// shadingPoints().
struct LookupLeak {
    double floor = 0.0, wall = 0.0;
};
inline LookupLeak lookupLeak(const std::vector<ShadingPoint>& points, const std::vector<glm::vec3>& irradiance) {
    double sum[2][2] = {}, count[2][2] = {};
    for (std::size_t i = 0; i < points.size(); ++i) {
        const int f = points[i].floor ? 1 : 0, d = points[i].dark ? 1 : 0;
        sum[f][d] += double(irradiance[i].x);
        count[f][d] += 1.0;
    }
    auto mean = [&](int f, int d) { return sum[f][d] / std::max(count[f][d], 1.0); };
    return {mean(1, 1) / mean(1, 0), mean(0, 1) / mean(0, 0)};
}

} // namespace lpv::renderer::thinwall
