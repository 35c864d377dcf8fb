#pragma once
// Where the LPV cascades lie and how the sun sees each of them: the CPU math
// behind the reflective-shadow-map tiles (RsmPass) and, later, the LPV grids.
//
// Cascade k is an axis-aligned cube of gridSize^3 cells of size
// cellSize * 2^k around the camera, its centre moved ahead of the camera along
// the view direction by viewShift times (half its extent less two cells: the
// camera keeps two cells behind it) (Kaplanyan and
// Dachsbacher place cascades so: with the camera at the centre half of the
// finest cascade lies behind it). With snapping on, its corner sits on a
// multiple of its own cell size, so the grid does not swim as the camera
// moves (it jumps by whole cells instead). Cascade k+1 contains cascade k
// (for gridSize >= 4 and viewShift in [0, 1]: the shift grows with the extent,
// so the coarser cube reaches further both ahead and behind) and its cell
// corners are also cell corners of cascade k.
//
// RSM tile k is an orthographic view along the sun's direction that covers
// cascade k: its window is the cube's bounding box in light space, made
// square, and snapped to the tile's texel grid so a texel always sees the
// same piece of the world while the cube stays put. Its depth range reaches
// back toward the sun to the scene's bounds, so a caster above the cube
// still shadows (and hides) what lies below it.
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::renderer {

// The most cascades an RSM renders in one pass (rsm.cascades' upper bound;
// also the size of the per-tile uniform arrays in shaders/rsm.geom).
inline constexpr int kMaxRsmCascades = 6;

// The sun: the scene's first directional light; -1 if it has none.
int findSun(const scene::Scene& scene);

struct LpvCascade {
    glm::vec3 origin{0.0f}; // world-space minimum corner
    float cellSize = 1.0f;  // world units
    int gridSize = 1;       // cells along each axis

    float extent() const { return cellSize * float(gridSize); }
    scene::Bounds bounds() const { return {origin, origin + glm::vec3(extent())}; }
    bool operator==(const LpvCascade&) const = default;
};

struct LpvCascadeSettings {
    int cascades = 4;
    int gridSize = 32;
    float cellSize = 0.25f; // of cascade 0
    bool snapToCells = true;
    float viewShift = 0.0f; // lpv.viewShift: centre ahead of the camera, 0..1 of (half extent - 2 cells)
    // lpv.clampToScene: where not empty, each cascade is moved (as little as
    // it can) so that along each axis it covers as much of these bounds as
    // its extent allows: a cascade larger than the scene holds all of it, a
    // smaller one lies inside it. Cells outside the scene hold no light.
    scene::Bounds sceneBounds{};
};

// The cascade settings of a frame from its parameters (lpv.gridSize,
// lpv.cellSize, lpv.cellSnapping, lpv.viewShift, lpv.clampToScene) for
// `count` cascades: the RSM tiles and the LPV volumes must agree on them.
LpvCascadeSettings lpvCascadeSettings(const scene::ParameterSet& params, int count,
                                      const scene::Bounds& sceneBounds = {});

// Cascade `k` (0 = finest) around `camera`, shifted along `viewDirection`
// (need not be unit length; zero means no shift).
LpvCascade lpvCascade(const glm::vec3& camera, const glm::vec3& viewDirection, int k,
                      const LpvCascadeSettings& settings);
std::vector<LpvCascade> lpvCascades(const glm::vec3& camera, const glm::vec3& viewDirection,
                                    const LpvCascadeSettings& settings);
// Unshifted: the cubes centred on `camera` (tests and callers without a view).
LpvCascade lpvCascade(const glm::vec3& camera, int k, const LpvCascadeSettings& settings);
std::vector<LpvCascade> lpvCascades(const glm::vec3& camera, const LpvCascadeSettings& settings);

struct RsmTile {
    LpvCascade cascade;   // the cube this tile covers
    glm::mat4 view{1.0f}; // world -> light space (a rotation; the sun looks down -z)
    glm::mat4 projection{1.0f};
    glm::mat4 viewProj{1.0f};
    float texelSize = 0.0f;    // width = height of one texel in world units, across the sun's rays
    float texelArea = 0.0f;    // texelSize^2: area of a texel on a plane facing the sun
    glm::vec2 windowMin{0.0f}; // light-space x, y of the tile's edges, on multiples of texelSize
    glm::vec2 windowMax{0.0f};
    float nearDepth = 0.0f; // light-space depth range of the projection (distance along the rays)
    float farDepth = 0.0f;
};

// Rotation from world to light space for a sun travelling along `direction`
// (x, y across the rays, the sun looking down -z). Independent of the camera,
// so texel snapping in light space is stable.
glm::mat4 sunView(const glm::vec3& direction);

// Tile for one cascade. `sceneBounds` (may be empty) extends the depth range
// toward the sun; `tileSize` is the tile's width and height in texels (>= 2).
RsmTile makeRsmTile(const LpvCascade& cascade, const glm::vec3& sunDirection,
                    const scene::Bounds& sceneBounds, int tileSize);

// One orthographic view-projection holding every tile (they share the sun's
// rotation): draw items outside it are culled before the single RSM pass.
glm::mat4 rsmUnionViewProj(const std::vector<RsmTile>& tiles);

// The light-space bounding box (view space of sunView) of `box`.
scene::Bounds lightSpaceBounds(const glm::mat4& view, const scene::Bounds& box);

} // namespace lpv::renderer
