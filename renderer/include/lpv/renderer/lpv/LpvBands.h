#pragma once
// The CPU reference of the LPV for two or three SH bands (issue #47,
// lpv.shBands): injection of VPLs and sky light, the geometry volume's
// occlusion, propagation through its face-transfer terms and the lookup's
// irradiance convolution, written once for B bands (ShBands.h). With B = 2
// it computes what LpvReference.h computes (a test holds them together);
// B = 3 is the higher-order LPV the GPU passes are to match. The grids,
// VPLs, surfels, faces and height maps are LpvReference.h's.
#include "lpv/renderer/lpv/LpvReference.h"
#include "lpv/renderer/lpv/ShBands.h"

#include <span>
#include <vector>

namespace lpv::renderer::lpvref::bands {

// Per cell and colour channel the SH of the radiant intensity (W/sr), cells indexed as ShGrid.
template <int B>
struct Grid {
    int n = 0;
    std::vector<sh::Coeffs<B>> channel[3];

    explicit Grid(int cells = 0);
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n) * (std::size_t(y) + std::size_t(n) * std::size_t(z));
    }
    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n; }
    sh::Coeffs<B>& at(int c, int x, int y, int z) { return channel[c][index(x, y, z)]; }
    const sh::Coeffs<B>& at(int c, int x, int y, int z) const { return channel[c][index(x, y, z)]; }
    Grid& operator+=(const Grid& other);
};

// The blocking potential in B bands: (n + 1)^3 cells on the LPV cell corners, as GvGrid.
template <int B>
struct Gv {
    int n = 0;
    std::vector<sh::Coeffs<B>> potential;
    float strength = 1.0f; // lpv.occlusionStrength
    bool twoSided = false; // lpv.twoSidedOcclusion

    explicit Gv(int lpvCells = 0);
    std::size_t index(int x, int y, int z) const {
        const std::size_t m = std::size_t(n) + 1;
        return std::size_t(x) + m * (std::size_t(y) + m * std::size_t(z));
    }
    bool inside(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x <= n && y <= n && z <= n; }
    const sh::Coeffs<B>& at(int x, int y, int z) const { return potential[index(x, y, z)]; }
    sh::Coeffs<B> sample(const glm::vec3& g) const; // trilinear, zero outside 0..n
};

// The face-transfer terms of a gather (docs/lpv.md, "Three bands"): for each
// of the 30 (travel direction, face) pairs, what the source's SH is dotted
// with to give the flux through the face, omega_f Y(dir_f), and the SH the
// flux re-enters the destination with, cosineLobe(n_f) / pi. A step is then
// I_p += sum_f max(0, I_q . gather_f) T_f w_f emit_f.
template <int B>
struct FaceTransfer {
    PropagationFace face;
    sh::Coeffs<B> gather;
    sh::Coeffs<B> emit;
};
template <int B>
const std::vector<FaceTransfer<B>>& faceTransfers();

template <int B>
Grid<B> injectVpls(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells);
template <int B>
Grid<B> injectSky(const GridFrame& grid, const HeightMap& map, const glm::vec3& radiance);
template <int B>
Gv<B> injectSurfels(const GridFrame& grid, std::span<const Surfel> surfels);
// 1 - clamp(strength B(-travel)) (two-sided: the larger of B(-travel) and B(travel)).
template <int B>
float transmittance(const Gv<B>& gv, const glm::vec3& g, const glm::vec3& travel);

// One gather step; `gv` null = no occlusion, `normals` null = undirected.
template <int B>
Grid<B> propagateStep(const Grid<B>& source, const Gv<B>* gv, const NormalGrid* normals = nullptr);
template <int B>
Grid<B> propagateAndAccumulate(const Grid<B>& injected, const Gv<B>* gv, int steps,
                               const NormalGrid* normals = nullptr, bool occludeFirstStep = true);

// Total flux (W) of one channel: the DC coefficients summed times 4 pi Y00.
template <int B>
double totalFlux(const Grid<B>& grid, int channel);
template <int B>
sh::Coeffs<B> sampleTrilinear(const Grid<B>& grid, int channel, const glm::vec3& u);
// Indirect irradiance (rgb) at x with normal n: max(0, I(u) . cosineLobe(-n)) / s^2.
template <int B>
glm::vec3 irradianceAt(const Grid<B>& accumulated, const GridFrame& grid, const glm::vec3& x, const glm::vec3& n,
                       float lookupOffsetCells = 0.0f);

} // namespace lpv::renderer::lpvref::bands
