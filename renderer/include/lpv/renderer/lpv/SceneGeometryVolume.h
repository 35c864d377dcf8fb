#pragma once
// The geometry volume of the whole scene (lpv.geometrySource = scene;
// docs/lpv.md, "Geometry volume from the scene"): every visible triangle cut
// into surfels on the CPU, binned once per scene change into one sparse
// world-aligned GV per cascade level, and each frame a cascade's GV is the
// window of its level under the cascade. The RSM and the camera see only the
// surfaces the sun and the view reach; this holds every wall, both faces of
// it, wherever the cascades go, and does not move when the camera turns.
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace lpv::renderer::lpvref {

// Surfels of every visible object's triangles: each triangle cut into m^2
// equal sub-triangles, m = ceil(longest edge / spacing) (at most 256), one
// surfel at each centroid with the triangle's area / m^2, facing the side
// its shading normals face.
std::vector<Surfel> sampleSceneSurfels(const scene::Scene& scene, float spacing);
// How many surfels sampleSceneSurfels gives, without making them.
std::size_t countSceneSurfels(const scene::Scene& scene, float spacing);

// The GV of surfels on the world grid of one cell size: world GV cell c
// (integer) is centred at c * cellSize and sums, over the surfels nearest to
// it (floor(p / cellSize + 0.5)), min(A / cellSize^2, 1) cosineLobe(n), as
// injectSurfels does for one cascade. Sparse: only cells a surfel reached,
// sorted by z, then y, then x. Cells beyond 2^20 from the origin are dropped.
// With three SH bands (lpv.shBands = 3, issue #47) each cell also sums band 2
// of the lobes (coefficients 4-8 of ShBands.h), in `band2`, parallel to
// `cells`; it is empty for two bands.
using GvBand2 = std::array<float, 5>;
struct WorldGv {
    float cellSize = 1.0f;
    std::vector<std::pair<std::uint64_t, glm::vec4>> cells;
    std::vector<GvBand2> band2;

    static constexpr int kCoordinateBias = 1 << 20;
    static bool representable(const glm::ivec3& c);
    static std::uint64_t key(const glm::ivec3& c); // c must be representable
    glm::vec4 at(const glm::ivec3& c) const;       // zero where no surfel reached
};
WorldGv buildWorldGv(std::span<const Surfel> surfels, float cellSize, int bands = 2);

// One world GV per cascade level, level k sampled at spacing cellSizes[k] / 2
// (wider where the scene's objects, hidden ones too, would give more than
// maxSurfelsPerLevel surfels).
struct SceneGv {
    std::vector<WorldGv> levels;
    std::vector<float> spacing;        // per level, as sampled
    std::vector<std::size_t> surfels;  // per level
};
SceneGv buildSceneGv(const scene::Scene& scene, std::span<const float> cellSizes, std::size_t maxSurfelsPerLevel,
                     int bands = 2);

// The scene's GV kept per object, so that an edit samples again only the
// objects it moved, hid, showed or added (the editor drags one object at a
// time): each object's cells per level, summed over the objects in their
// order into gv(). buildSceneGv is one update of an empty cache, so both
// give the same sums. The spacing is chosen when the cache is (re)filled.
class SceneGvCache {
  public:
    // Brings gv() up to date with `scene`; returns how many objects were
    // sampled. `bands` 3 sums band 2 as well (a change of bands samples again).
    int update(const scene::Scene& scene, std::span<const float> cellSizes, std::size_t maxSurfelsPerLevel,
               int bands = 2);
    // The meshes changed (another scene): the next update samples every object.
    void clear();
    const SceneGv& gv() const { return gv_; }

  private:
    struct ObjectCells {
        bool sampled = false;
        std::uint64_t placement = 0; // mesh, visibility and world matrix it was sampled with
        std::vector<std::vector<std::pair<std::uint64_t, glm::vec4>>> levels;
        std::vector<std::vector<GvBand2>> band2; // per level, parallel to levels (three bands)
        std::vector<std::size_t> surfels;
    };
    std::vector<ObjectCells> objects_;
    std::vector<float> cellSizes_;
    std::size_t maxSurfels_ = 0;
    int bands_ = 2;
    SceneGv gv_;
};

// The GV of cascade `grid` read from `world` (same cell size): GV cell g holds
// world cell floor(origin / cellSize + 0.5) + g. Where the origin is a
// multiple of the cell size (lpv.cellSnapping), this is injectSurfels(grid,
// surfels) of the surfels `world` was built from, up to float rounding of
// surfels exactly between two cells; otherwise the cascade reads the nearest
// world cells, at most half a cell off.
GvGrid windowOf(const WorldGv& world, const GridFrame& grid);
// The same into `out`, (grid.n + 1)^3 cells (x fastest), which it overwrites
// (the renderer cuts every cascade's window into one buffer each frame).
void windowInto(const WorldGv& world, const GridFrame& grid, std::span<glm::vec4> out);
// Band 2 of the same window (a world GV built with three bands) into `out`,
// 2 (grid.n + 1)^3 values: per GV cell (Y2-2, Y2-1, Y20, Y21) and (Y22, 0,
// 0, 0), the layout of LpvVolumes::geometryHigh.
void windowBand2Into(const WorldGv& world, const GridFrame& grid, std::span<glm::vec4> out);

} // namespace lpv::renderer::lpvref
