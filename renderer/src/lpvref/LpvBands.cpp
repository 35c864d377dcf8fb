#include "lpv/renderer/lpv/LpvBands.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lpv::renderer::lpvref::bands {

namespace {

// 4 pi Y00: the higher bands integrate to zero over the sphere.
constexpr double kDcToFlux = 3.5449077018110318;

template <int B>
using Sum = std::array<double, std::size_t(B * B)>;

template <int B>
void accumulate(Sum<B>& sum, double weight, const sh::Coeffs<B>& f) {
    for (int i = 0; i < B * B; ++i)
        sum[std::size_t(i)] += weight * double(f[i]);
}

template <int B>
sh::Coeffs<B> toCoeffs(const Sum<B>& sum) {
    sh::Coeffs<B> out;
    for (int i = 0; i < B * B; ++i)
        out[i] = float(sum[std::size_t(i)]);
    return out;
}

// The corner weights of trilinear interpolation: corner o of the cell at `f`.
double cornerWeight(const glm::ivec3& o, const glm::vec3& f) {
    return double(o.x ? f.x : 1.0f - f.x) * double(o.y ? f.y : 1.0f - f.y) * double(o.z ? f.z : 1.0f - f.z);
}

} // namespace

template <int B>
Grid<B>::Grid(int cells) : n(cells) {
    const std::size_t count = std::size_t(cells) * std::size_t(cells) * std::size_t(cells);
    for (auto& c : channel)
        c.assign(count, sh::Coeffs<B>{});
}

template <int B>
Grid<B>& Grid<B>::operator+=(const Grid& other) {
    assert(other.n == n && "grids of different sizes");
    for (int c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < channel[c].size(); ++i)
            channel[c][i] += other.channel[c][i];
    return *this;
}

template <int B>
Gv<B>::Gv(int lpvCells) : n(lpvCells) {
    const std::size_t m = std::size_t(lpvCells) + 1;
    potential.assign(m * m * m, sh::Coeffs<B>{});
}

template <int B>
sh::Coeffs<B> Gv<B>::sample(const glm::vec3& g) const {
    const glm::vec3 base = glm::floor(g);
    const glm::vec3 f = g - base;
    const glm::ivec3 b(base);
    Sum<B> sum{};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c = b + o;
        if (inside(c.x, c.y, c.z))
            accumulate<B>(sum, cornerWeight(o, f), at(c.x, c.y, c.z));
    }
    return toCoeffs<B>(sum);
}

template <int B>
const std::vector<FaceTransfer<B>>& faceTransfers() {
    static const std::vector<FaceTransfer<B>> table = [] {
        std::vector<FaceTransfer<B>> out;
        for (const PropagationFace& f : propagationFaces())
            out.push_back({f, f.solidAngle * sh::basisOf<B>(f.direction),
                           (1.0f / sh::kPi) * sh::cosineLobeOf<B>(f.normal)});
        return out;
    }();
    return table;
}

template <int B>
Grid<B> injectVpls(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells) {
    Grid<B> out(grid.n);
    for (const Vpl& v : vpls) {
        const glm::vec3 moved = v.position + v.normal * (offsetCells * grid.cellSize);
        const glm::ivec3 c(glm::floor((moved - grid.origin) / grid.cellSize));
        if (!out.inside(c.x, c.y, c.z))
            continue;
        for (int ch = 0; ch < 3; ++ch)
            out.at(ch, c.x, c.y, c.z) += sh::vplIntensityOf<B>(v.normal, v.flux[ch]);
    }
    return out;
}

template <int B>
Grid<B> injectSky(const GridFrame& grid, const HeightMap& map, const glm::vec3& radiance) {
    Grid<B> out(grid.n);
    const sh::Coeffs<B> lobe = sh::cosineLobeOf<B>({0.0f, -1.0f, 0.0f}); // light travelling down
    for (int z = 0; z < grid.n; ++z)
        for (int x = 0; x < grid.n; ++x) {
            const int y = skyInjectionCell(grid, map, x, z);
            if (y < 0)
                continue;
            for (int c = 0; c < 3; ++c)
                out.at(c, x, y, z) += (radiance[c] * grid.cellSize * grid.cellSize) * lobe;
        }
    return out;
}

template <int B>
Gv<B> injectSurfels(const GridFrame& grid, std::span<const Surfel> surfels) {
    Gv<B> out(grid.n);
    for (const Surfel& s : surfels) {
        const glm::ivec3 g(glm::floor((s.position - grid.origin) / grid.cellSize + 0.5f));
        if (!out.inside(g.x, g.y, g.z))
            continue;
        const float coverage = std::min(s.area / (grid.cellSize * grid.cellSize), 1.0f);
        out.potential[out.index(g.x, g.y, g.z)] += coverage * sh::cosineLobeOf<B>(s.normal);
    }
    return out;
}

template <int B>
float transmittance(const Gv<B>& gv, const glm::vec3& g, const glm::vec3& travel) {
    const sh::Coeffs<B> b = gv.sample(g);
    float blocked = sh::evaluateAt<B>(b, -travel);
    if (gv.twoSided)
        blocked = std::max(blocked, sh::evaluateAt<B>(b, travel));
    return 1.0f - std::clamp(gv.strength * blocked, 0.0f, 1.0f);
}

template <int B>
Grid<B> propagateStep(const Grid<B>& source, const Gv<B>* gv, const NormalGrid* normals) {
    const int n = source.n;
    Grid<B> out(n);
    const auto& faces = faceTransfers<B>();
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::ivec3 p(x, y, z);
                Sum<B> sum[3]{};
                for (const FaceTransfer<B>& t : faces) {
                    const PropagationFace& f = t.face;
                    const glm::ivec3 q = p - f.travel;
                    if (!source.inside(q.x, q.y, q.z))
                        continue;
                    const float through =
                        gv ? transmittance<B>(*gv, glm::vec3(q) + 0.5f + 0.5f * glm::vec3(f.travel), f.direction)
                           : 1.0f;
                    const float directed = normals ? directedWeight(f.normal, normals->at(x, y, z)) : 1.0f;
                    for (int c = 0; c < 3; ++c) {
                        // Negative lobes carry no light (fewer with three bands, still some).
                        const double flux = std::max(0.0, double(sh::dot(source.at(c, q.x, q.y, q.z), t.gather)));
                        accumulate<B>(sum[c], flux * double(through) * double(directed), t.emit);
                    }
                }
                for (int c = 0; c < 3; ++c)
                    out.at(c, x, y, z) = toCoeffs<B>(sum[c]);
            }
    return out;
}

template <int B>
Grid<B> propagateAndAccumulate(const Grid<B>& injected, const Gv<B>* gv, int steps, const NormalGrid* normals,
                               bool occludeFirstStep) {
    Grid<B> accumulated = injected;
    Grid<B> current = injected;
    for (int i = 0; i < steps; ++i) {
        current = propagateStep<B>(current, i == 0 && !occludeFirstStep ? nullptr : gv, normals);
        accumulated += current;
    }
    return accumulated;
}

template <int B>
double totalFlux(const Grid<B>& grid, int channel) {
    double dc = 0.0;
    for (const sh::Coeffs<B>& v : grid.channel[channel])
        dc += double(v[0]);
    return dc * kDcToFlux;
}

template <int B>
sh::Coeffs<B> sampleTrilinear(const Grid<B>& grid, int channel, const glm::vec3& u) {
    const glm::vec3 v = glm::clamp(u - 0.5f, glm::vec3(0.0f), glm::vec3(float(grid.n - 1)));
    const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(v)), glm::ivec3(grid.n - 1));
    const glm::ivec3 i1 = glm::min(i0 + 1, glm::ivec3(grid.n - 1));
    const glm::vec3 f = v - glm::vec3(i0);
    Sum<B> sum{};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c(o.x ? i1.x : i0.x, o.y ? i1.y : i0.y, o.z ? i1.z : i0.z);
        accumulate<B>(sum, cornerWeight(o, f), grid.at(channel, c.x, c.y, c.z));
    }
    return toCoeffs<B>(sum);
}

template <int B>
glm::vec3 irradianceAt(const Grid<B>& accumulated, const GridFrame& grid, const glm::vec3& x, const glm::vec3& n,
                       float lookupOffsetCells) {
    const glm::vec3 u = (x + n * (lookupOffsetCells * grid.cellSize) - grid.origin) / grid.cellSize;
    const float faceArea = grid.cellSize * grid.cellSize;
    glm::vec3 e(0.0f);
    for (int c = 0; c < 3; ++c)
        e[c] = sh::irradianceOf<B>(sampleTrilinear<B>(accumulated, c, u), n) / faceArea;
    return e;
}

#define LPV_BANDS_INSTANTIATE(B)                                                                                       \
    template struct Grid<B>;                                                                                           \
    template struct Gv<B>;                                                                                             \
    template const std::vector<FaceTransfer<B>>& faceTransfers<B>();                                                   \
    template Grid<B> injectVpls<B>(const GridFrame&, std::span<const Vpl>, float);                                     \
    template Grid<B> injectSky<B>(const GridFrame&, const HeightMap&, const glm::vec3&);                               \
    template Gv<B> injectSurfels<B>(const GridFrame&, std::span<const Surfel>);                                        \
    template float transmittance<B>(const Gv<B>&, const glm::vec3&, const glm::vec3&);                                 \
    template Grid<B> propagateStep<B>(const Grid<B>&, const Gv<B>*, const NormalGrid*);                                \
    template Grid<B> propagateAndAccumulate<B>(const Grid<B>&, const Gv<B>*, int, const NormalGrid*, bool);            \
    template double totalFlux<B>(const Grid<B>&, int);                                                                 \
    template sh::Coeffs<B> sampleTrilinear<B>(const Grid<B>&, int, const glm::vec3&);                                  \
    template glm::vec3 irradianceAt<B>(const Grid<B>&, const GridFrame&, const glm::vec3&, const glm::vec3&, float);

LPV_BANDS_INSTANTIATE(2)
LPV_BANDS_INSTANTIATE(3)

} // namespace lpv::renderer::lpvref::bands
