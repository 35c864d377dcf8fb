#pragma once
// A closed room in one cascade, for the multi-bounce tests (CPU reference and
// GPU): six inward-facing walls of geometry-volume surfels and, on the floor,
// a lit patch of VPLs facing up. 12^3 cells of 0.25 m; the walls lie on the
// GV planes 2 and 10, so the room is 8 cells wide inside.
#include "lpv/renderer/lpv/LpvReference.h"

#include <vector>

namespace lpv::renderer {

struct RoomScene {
    lpvref::GridFrame grid{glm::vec3(0.0f), 0.25f, 12};
    float lo = 0.5f, hi = 2.5f;          // the walls' planes on every axis
    float texel = 0.125f;                // surfel spacing: 2 x 2 per cell face
    std::vector<lpvref::Vpl> vpls;       // the lit patch of the floor
    std::vector<lpvref::Surfel> surfels; // the six walls, facing inward
};

// `litMaxX`: the floor is lit for x below it (a patch of sun on one side).
inline RoomScene closedRoom(float litMaxX = 1.5f, float fluxPerTexel = 0.01f) {
    RoomScene s;
    const int perSide = int((s.hi - s.lo) / s.texel + 0.5f);
    for (int i = 0; i < perSide; ++i)
        for (int j = 0; j < perSide; ++j) {
            const float a = s.lo + (float(i) + 0.5f) * s.texel, b = s.lo + (float(j) + 0.5f) * s.texel;
            const float area = s.texel * s.texel;
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    glm::vec3 p, n(0.0f);
                    p[axis] = side == 0 ? s.lo : s.hi;
                    p[(axis + 1) % 3] = a;
                    p[(axis + 2) % 3] = b;
                    n[axis] = side == 0 ? 1.0f : -1.0f;
                    s.surfels.push_back({p, n, area});
                }
            const glm::vec3 floor{a, s.lo, b};
            if (floor.x < litMaxX)
                s.vpls.push_back({floor,
                                  {0.0f, 1.0f, 0.0f},
                                  glm::vec3(fluxPerTexel, 0.8f * fluxPerTexel, 0.6f * fluxPerTexel)});
        }
    return s;
}

} // namespace lpv::renderer
