#pragma once
// A lit floor under a white box, for the directed-propagation tests (CPU
// reference and GPU): the floor's texels are VPLs facing up, the box's faces
// are geometry-volume surfels. One cascade of 16^3 cells of 0.25 m.
#include "lpv/renderer/lpv/LpvReference.h"

#include <vector>

namespace lpv::renderer {

struct DirectedScene {
    lpvref::GridFrame grid{glm::vec3(0.0f), 0.25f, 16};
    std::vector<lpvref::Vpl> vpls;       // the sunlit floor, y = floorY, normal +y
    std::vector<lpvref::Surfel> surfels; // the floor and the box's 6 faces
    float floorY = 0.6f;
    glm::vec3 boxMin{1.5f, 1.6f, 1.5f}, boxMax{2.5f, 2.4f, 2.5f};
};

inline DirectedScene floorUnderBox() {
    DirectedScene s;
    const float extent = s.grid.cellSize * float(s.grid.n);
    const int perSide = 2 * s.grid.n; // 2x2 texels per cell
    const float texel = extent / float(perSide);
    for (int i = 0; i < perSide; ++i)
        for (int j = 0; j < perSide; ++j) {
            const glm::vec3 p{(float(i) + 0.5f) * texel, s.floorY, (float(j) + 0.5f) * texel};
            // Under the box the floor is in its shadow: no VPL, but still a surface.
            const bool shadowed = p.x > s.boxMin.x && p.x < s.boxMax.x && p.z > s.boxMin.z && p.z < s.boxMax.z;
            if (!shadowed)
                s.vpls.push_back({p, {0, 1, 0}, glm::vec3(0.02f)});
            s.surfels.push_back({p, {0, 1, 0}, texel * texel});
        }
    // The box's faces, surfels on a 0.125 m grid.
    const float step = 0.125f;
    for (float a = s.boxMin.x + step / 2; a < s.boxMax.x; a += step)
        for (float b = s.boxMin.z + step / 2; b < s.boxMax.z; b += step) {
            s.surfels.push_back({{a, s.boxMin.y, b}, {0, -1, 0}, step * step});
            s.surfels.push_back({{a, s.boxMax.y, b}, {0, 1, 0}, step * step});
        }
    for (float a = s.boxMin.y + step / 2; a < s.boxMax.y; a += step)
        for (float b = s.boxMin.z + step / 2; b < s.boxMax.z; b += step) {
            s.surfels.push_back({{s.boxMin.x, a, b}, {-1, 0, 0}, step * step});
            s.surfels.push_back({{s.boxMax.x, a, b}, {1, 0, 0}, step * step});
        }
    for (float a = s.boxMin.x + step / 2; a < s.boxMax.x; a += step)
        for (float b = s.boxMin.y + step / 2; b < s.boxMax.y; b += step) {
            s.surfels.push_back({{a, b, s.boxMin.z}, {0, 0, -1}, step * step});
            s.surfels.push_back({{a, b, s.boxMax.z}, {0, 0, 1}, step * step});
        }
    return s;
}

struct DirectedFigures {
    double floor = 0.0;     // mean indirect irradiance (green) on the open floor, away from the box
    double underside = 0.0; // mean indirect irradiance (green) on the box's underside
};

inline DirectedFigures measure(const DirectedScene& s, const lpvref::ShGrid& accumulated) {
    DirectedFigures f;
    int floorPoints = 0, undersidePoints = 0;
    const float extent = s.grid.cellSize * float(s.grid.n);
    for (float x = 0.3f; x < extent - 0.3f; x += 0.1f)
        for (float z = 0.3f; z < extent - 0.3f; z += 0.1f) {
            const bool nearBox = x > s.boxMin.x - 0.5f && x < s.boxMax.x + 0.5f && z > s.boxMin.z - 0.5f &&
                                 z < s.boxMax.z + 0.5f;
            if (!nearBox) {
                f.floor += lpvref::irradianceAt(accumulated, s.grid, {x, s.floorY, z}, {0, 1, 0}).g;
                ++floorPoints;
            }
            if (x > s.boxMin.x && x < s.boxMax.x && z > s.boxMin.z && z < s.boxMax.z) {
                f.underside += lpvref::irradianceAt(accumulated, s.grid, {x, s.boxMin.y, z}, {0, -1, 0}).g;
                ++undersidePoints;
            }
        }
    f.floor /= std::max(floorPoints, 1);
    f.underside /= std::max(undersidePoints, 1);
    return f;
}

} // namespace lpv::renderer
