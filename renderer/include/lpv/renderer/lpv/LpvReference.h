#pragma once
// The CPU reference of the LPV: injection, geometry volume, propagation and
// lookup in plain C++ on small grids, exactly as docs/lpv.md writes them down.
// Slow and simple on purpose: the GPU passes (renderer/src/passes/lpv/LpvPass.*) are
// tested against it, variant by variant.
#include "lpv/renderer/lpv/Sh.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace lpv::renderer::lpvref {

// One cascade: minimum corner, cell size, cells per axis.
struct GridFrame {
    glm::vec3 origin{0.0f};
    float cellSize = 1.0f;
    int n = 8;
};

// Per cell and colour channel the SH of the radiant intensity (W/sr).
// Cell (x, y, z) is at index x + n * (y + n * z).
struct ShGrid {
    int n = 0;
    std::vector<glm::vec4> channel[3];

    explicit ShGrid(int cells = 0);
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n) * (std::size_t(y) + std::size_t(n) * std::size_t(z));
    }
    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n; }
    glm::vec4& at(int c, int x, int y, int z) { return channel[c][index(x, y, z)]; }
    const glm::vec4& at(int c, int x, int y, int z) const { return channel[c][index(x, y, z)]; }
    ShGrid& operator+=(const ShGrid& other);
};

// The blocking potential: (n + 1)^3 cells centred on the LPV cell corners
// (GV cell g sits at origin + g * cellSize), one colourless SH each.
struct GvGrid {
    int n = 0; // LPV cells per axis; the GV has n + 1 per axis
    std::vector<glm::vec4> potential;
    // lpv.occlusionStrength: propagation reads strength * B (docs/lpv.md,
    // Propagation); the stored potential (which bounces read) is unscaled.
    float strength = 1.0f;
    // lpv.twoSidedOcclusion: a surfel blocks light from both sides.
    bool twoSided = false;

    explicit GvGrid(int lpvCells = 0);
    int size() const { return n + 1; }
    std::size_t index(int x, int y, int z) const {
        const std::size_t m = std::size_t(n) + 1;
        return std::size_t(x) + m * (std::size_t(y) + m * std::size_t(z));
    }
    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x <= n && y <= n && z <= n; }
    glm::vec4& at(int x, int y, int z) { return potential[index(x, y, z)]; }
    const glm::vec4& at(int x, int y, int z) const { return potential[index(x, y, z)]; }
    // Trilinear interpolation at GV coordinate `g` (cell centres at integers);
    // cells outside 0..n count as zero.
    glm::vec4 sample(const glm::vec3& g) const;
};

// A virtual point light: an RSM texel.
struct Vpl {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec3 flux{0.0f}; // W, per colour channel
};

// A piece of surface for the geometry volume; `area` in square world units.
struct Surfel {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float area = 0.0f;
};

// The 30 (direction, face) pairs of a gather (docs/lpv.md, Propagation).
struct PropagationFace {
    glm::ivec3 travel;    // d: from the source neighbour q to the destination p = q + d
    glm::vec3 normal;     // n_f: outward normal of the face of p the light leaves through
    glm::vec3 direction;  // dir_f = normalize(d + 0.5 n_f)
    float solidAngle;     // omega_f, sr
};
inline constexpr float kFrontFaceSolidAngle = 0.4006696846f;
inline constexpr float kSideFaceSolidAngle = 0.4234313544f;
const std::vector<PropagationFace>& propagationFaces();

// Injection: every VPL moved by offsetCells * cellSize along its normal, into the cell it falls in.
ShGrid injectVpls(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells);

// Geometry volume: surfels into the GV cell nearest to them, summed.
GvGrid injectSurfels(const GridFrame& grid, std::span<const Surfel> surfels);
// The camera G-buffer as the geometry volume reads it (the previous frame's):
// depth in [0, 1] and normals (w > 0 where a surface was seen) per pixel,
// row by row from the bottom, with the camera that rendered it.
struct CameraGBuffer {
    int width = 0, height = 0;
    std::vector<float> depth;
    std::vector<glm::vec4> normal;
    glm::mat4 inverseViewProj{1.0f};
    glm::vec3 position{0.0f};
    float pixelAngle = 0.0f; // 2 tan(fovY / 2) / height
};
// Its surfels, as lpv_gv_inject.comp (GV_FROM_CAMERA) makes them: one per
// stride x stride block of pixels (lpv.gvCameraStride), from the block's
// middle pixel (x * stride + stride / 2; a block whose middle pixel lies
// outside the image gives none), at the pixel's world position with its
// normal, area (stride d pixelAngle)^2 / max(|n.v|, 0.2), d its distance to
// the camera and v the direction to it. Non-finite pixels are skipped.
std::vector<Surfel> cameraSurfels(const CameraGBuffer& gbuffer, int stride);
// Per GV cell, the SH of the two with the larger DC coefficient.
GvGrid mergeByMax(const GvGrid& a, const GvGrid& b);
// Transmittance of light travelling along unit `travel` through GV coordinate
// `g`: 1 - clamp(strength B(-travel)), or with gv.twoSided
// 1 - clamp(strength max(B(-travel), B(travel))).
float transmittance(const GvGrid& gv, const glm::vec3& g, const glm::vec3& travel);

// Directed propagation (docs/lpv.md): per cell the average unit normal of the
// VPLs injected into it (xyz) and whether any was (w = 1), then dilated.
struct NormalGrid {
    int n = 0;
    std::vector<glm::vec4> normal; // index as ShGrid

    explicit NormalGrid(int cells = 0);
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n) * (std::size_t(y) + std::size_t(n) * std::size_t(z));
    }
    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n; }
    const glm::vec4& at(int x, int y, int z) const { return normal[index(x, y, z)]; }
};
// The VPLs' normals, averaged per cell they are injected into (same cell as injectVpls).
NormalGrid injectNormals(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells);
// One dilation: a cell without normals takes the average of its 6 neighbours that have one.
NormalGrid dilateNormals(const NormalGrid& normals);
// The weight of light re-emitted into a cell along face normal n_f, given the
// cell's (dilated) normal d: min(1, 1 + n_f . d). Light heading back into the
// surface that emitted it (n_f = -d) is removed; sideways or away it is kept.
float directedWeight(const glm::vec3& faceNormal, const glm::vec4& cellNormal);

// Sky light injection (docs/lpv.md): a top-down height map of the highest
// surface per texel (texel (i, j) covers min + [i, i+1] x [j, j+1] texelSize
// in x and z; -infinity where nothing is). Per column of cells the highest
// surface over the texels whose centres lie in the column (the texel under the
// column's centre if none does); the first cell above it receives a VPL
// facing down with flux pi * radiance * cellSize^2 (the sky's irradiance on
// the cell's top face).
struct HeightMap {
    glm::vec2 min{0.0f}; // world x, z of texel (0, 0)'s corner
    float texelSize = 1.0f;
    int size = 0;
    std::vector<float> height; // texel (i, j) at i + size * j
};
float columnTop(const HeightMap& map, float x0, float z0, float x1, float z1);
// The cell of column (x, z) the sky's light is injected into: the first
// above the highest surface of the column (0 when that lies below the
// cascade), or -1 when the column is covered above the cascade's top.
int skyInjectionCell(const GridFrame& grid, const HeightMap& map, int x, int z);
ShGrid injectSky(const GridFrame& grid, const HeightMap& map, const glm::vec3& radiance);

// One propagation step (gather); `gv` null = no occlusion, `normals` null = undirected.
ShGrid propagateStep(const ShGrid& source, const GvGrid* gv, const NormalGrid* normals = nullptr);
// V_0 + V_1 + ... + V_steps, V_0 = injected. With occludeFirstStep false
// (lpv.occlusionFirstStep) the step from V_0 to V_1 ignores the GV: the light
// leaves the cell it was injected into past the surface that injected it.
ShGrid propagateAndAccumulate(const ShGrid& injected, const GvGrid* gv, int steps,
                              const NormalGrid* normals = nullptr, bool occludeFirstStep = true);

// Total flux (W) of all cells of one channel: the integral of I over the sphere, summed.
double totalFlux(const ShGrid& grid, int channel);
// Trilinear sample of channel c at cell coordinate `u` (centres at integer + 0.5, clamped to the grid).
glm::vec4 sampleTrilinear(const ShGrid& grid, int channel, const glm::vec3& u);
// Indirect irradiance (rgb) at world position x with normal n, from one cascade's accumulator.
// `lookupOffsetCells` (lpv.lookupOffset) moves x that many cells along n first.
glm::vec3 irradianceAt(const ShGrid& accumulated, const GridFrame& grid, const glm::vec3& x, const glm::vec3& n,
                       float lookupOffsetCells = 0.0f);

} // namespace lpv::renderer::lpvref
