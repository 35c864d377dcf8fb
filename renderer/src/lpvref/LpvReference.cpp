#include "lpv/renderer/lpv/LpvReference.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace lpv::renderer::lpvref {

namespace {

using glm::dvec4;

// The six axis directions, the only travel directions and face normals of a gather.
constexpr std::array<glm::ivec3, 6> kAxes{glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                                          glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)};

// The integral over the sphere of the DC basis function, 4 pi Y00 = 2 sqrt(pi): the
// linear band integrates to zero, so a cell's flux is its DC coefficient times this.
constexpr double kDcToFlux = 3.5449077018110318;

// The cell a cell coordinate falls in; the caller drops those outside the grid.
glm::ivec3 cellOf(const glm::vec3& cellCoordinate) { return glm::ivec3(glm::floor(cellCoordinate)); }

// Round half up rather than std::round's half away from zero: GLSL round() leaves
// halves to the implementation, floor(x + 0.5) is what both sides can agree on.
glm::ivec3 nearestGvCell(const glm::vec3& gvCoordinate) { return glm::ivec3(glm::floor(gvCoordinate + 0.5f)); }

} // namespace

ShGrid::ShGrid(int cells) : n(cells) {
    const std::size_t count = std::size_t(cells) * std::size_t(cells) * std::size_t(cells);
    for (auto& c : channel)
        c.assign(count, glm::vec4(0.0f));
}

ShGrid& ShGrid::operator+=(const ShGrid& other) {
    assert(other.n == n && "grids of different sizes");
    for (int c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < channel[c].size(); ++i)
            channel[c][i] += other.channel[c][i];
    return *this;
}

GvGrid::GvGrid(int lpvCells) : n(lpvCells) {
    const std::size_t m = std::size_t(lpvCells) + 1;
    potential.assign(m * m * m, glm::vec4(0.0f));
}

glm::vec4 GvGrid::sample(const glm::vec3& g) const {
    // No clamping: the GV ends with its last cell, beyond it nothing blocks.
    const glm::vec3 base = glm::floor(g);
    const glm::vec3 f = g - base;
    const glm::ivec3 b(base);
    dvec4 sum(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c = b + o;
        if (!inside(c.x, c.y, c.z))
            continue;
        const double w = double(o.x ? f.x : 1.0f - f.x) * double(o.y ? f.y : 1.0f - f.y) *
                         double(o.z ? f.z : 1.0f - f.z);
        sum += w * dvec4(at(c.x, c.y, c.z));
    }
    return glm::vec4(sum);
}

const std::vector<PropagationFace>& propagationFaces() {
    // Built once and never changed: a constant table, not mutable state.
    static const std::vector<PropagationFace> faces = [] {
        std::vector<PropagationFace> out;
        for (const glm::ivec3& d : kAxes)
            for (const glm::ivec3& nf : kAxes) {
                if (nf == -d)
                    continue; // the face shared with the source neighbour q: light enters there
                const bool front = nf == d;
                out.push_back({d, glm::vec3(nf), glm::normalize(glm::vec3(d) + 0.5f * glm::vec3(nf)),
                               front ? kFrontFaceSolidAngle : kSideFaceSolidAngle});
            }
        return out;
    }();
    return faces;
}

ShGrid injectVpls(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells) {
    ShGrid out(grid.n);
    for (const Vpl& v : vpls) {
        // Moved off its surface so that its own wall does not hide it from the cells in front.
        const glm::vec3 moved = v.position + v.normal * (offsetCells * grid.cellSize);
        const glm::ivec3 c = cellOf((moved - grid.origin) / grid.cellSize);
        if (!out.inside(c.x, c.y, c.z))
            continue;
        for (int ch = 0; ch < 3; ++ch)
            out.at(ch, c.x, c.y, c.z) += sh::vplIntensity(v.normal, v.flux[ch]);
    }
    return out;
}

GvGrid injectSurfels(const GridFrame& grid, std::span<const Surfel> surfels) {
    GvGrid out(grid.n);
    for (const Surfel& s : surfels) {
        const glm::ivec3 g = nearestGvCell((s.position - grid.origin) / grid.cellSize);
        if (!out.inside(g.x, g.y, g.z))
            continue;
        // The fraction of a cell face the surfel covers; one surfel cannot block more than all of it.
        const float coverage = std::min(s.area / (grid.cellSize * grid.cellSize), 1.0f);
        out.at(g.x, g.y, g.z) += coverage * sh::cosineLobe(s.normal);
    }
    return out;
}

std::vector<Surfel> cameraSurfels(const CameraGBuffer& g, int stride) {
    stride = std::max(stride, 1);
    std::vector<Surfel> out;
    auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (int by = 0; by * stride < g.height; ++by)
        for (int bx = 0; bx * stride < g.width; ++bx) {
            const int x = bx * stride + stride / 2, y = by * stride + stride / 2;
            if (x >= g.width || y >= g.height)
                continue;
            const std::size_t i = std::size_t(x) + std::size_t(g.width) * std::size_t(y);
            const glm::vec4 normal = g.normal[i];
            if (normal.w <= 0.0f)
                continue;
            const glm::vec2 ndc = (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(float(g.width), float(g.height)) *
                                      2.0f -
                                  1.0f;
            const glm::vec4 world = g.inverseViewProj * glm::vec4(ndc, g.depth[i] * 2.0f - 1.0f, 1.0f);
            const glm::vec3 p = glm::vec3(world) / world.w;
            const glm::vec3 rawNormal(normal);
            if (!finite(p) || !finite(rawNormal) || glm::dot(rawNormal, rawNormal) <= 1e-12f)
                continue;
            const glm::vec3 n = glm::normalize(rawNormal);
            const glm::vec3 toCamera = g.position - p;
            const float dist = glm::length(toCamera);
            const float side = dist * g.pixelAngle * float(stride);
            const float cosine = std::abs(glm::dot(n, toCamera / std::max(dist, 1e-6f)));
            out.push_back({p, n, side * side / std::max(cosine, 0.2f)});
        }
    return out;
}

GvGrid mergeByMax(const GvGrid& a, const GvGrid& b) {
    assert(a.n == b.n && "geometry volumes of different sizes");
    GvGrid out(a.n);
    // The larger DC is the larger blocking area: a wall seen by both sources counts once.
    for (std::size_t i = 0; i < out.potential.size(); ++i)
        out.potential[i] = b.potential[i].x > a.potential[i].x ? b.potential[i] : a.potential[i];
    return out;
}

float transmittance(const GvGrid& gv, const glm::vec3& g, const glm::vec3& travel) {
    // A surfel blocks light that hits its front, i.e. travels against its
    // normal; two-sided, light that reaches its back as well.
    const glm::vec4 b = gv.sample(g);
    float blocked = sh::evaluate(b, -travel);
    if (gv.twoSided)
        blocked = std::max(blocked, sh::evaluate(b, travel));
    return 1.0f - std::clamp(gv.strength * blocked, 0.0f, 1.0f);
}

NormalGrid::NormalGrid(int cells) : n(cells) {
    normal.assign(std::size_t(cells) * std::size_t(cells) * std::size_t(cells), glm::vec4(0.0f));
}

NormalGrid injectNormals(const GridFrame& grid, std::span<const Vpl> vpls, float offsetCells) {
    NormalGrid out(grid.n);
    std::vector<int> count(out.normal.size(), 0);
    std::vector<glm::dvec3> sum(out.normal.size(), glm::dvec3(0.0));
    for (const Vpl& v : vpls) {
        const glm::vec3 moved = v.position + v.normal * (offsetCells * grid.cellSize);
        const glm::ivec3 c = cellOf((moved - grid.origin) / grid.cellSize);
        if (!out.inside(c.x, c.y, c.z))
            continue;
        const std::size_t i = out.index(c.x, c.y, c.z);
        sum[i] += glm::dvec3(glm::normalize(v.normal));
        ++count[i];
    }
    for (std::size_t i = 0; i < out.normal.size(); ++i)
        if (count[i] > 0)
            out.normal[i] = glm::vec4(glm::vec3(sum[i] / double(count[i])), 1.0f);
    return out;
}

NormalGrid dilateNormals(const NormalGrid& normals) {
    NormalGrid out = normals;
    const int n = normals.n;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                if (normals.at(x, y, z).w > 0.0f)
                    continue; // a cell keeps the normals of its own VPLs
                glm::vec3 sum(0.0f);
                int count = 0;
                for (const glm::ivec3& d : kAxes) {
                    const glm::ivec3 q = glm::ivec3(x, y, z) + d;
                    if (normals.inside(q.x, q.y, q.z) && normals.at(q.x, q.y, q.z).w > 0.0f) {
                        sum += glm::vec3(normals.at(q.x, q.y, q.z));
                        ++count;
                    }
                }
                if (count > 0)
                    out.normal[out.index(x, y, z)] = glm::vec4(sum / float(count), 1.0f);
            }
    return out;
}

float directedWeight(const glm::vec3& faceNormal, const glm::vec4& cellNormal) {
    return std::min(1.0f, 1.0f + glm::dot(faceNormal, glm::vec3(cellNormal)));
}

float columnTop(const HeightMap& map, float x0, float z0, float x1, float z1) {
    // Texels whose centres lie in [x0, x1) x [z0, z1).
    auto first = [&](float w, float lo) { return int(std::ceil((w - lo) / map.texelSize - 0.5f)); };
    int i0 = first(x0, map.min.x), i1 = first(x1, map.min.x) - 1;
    int j0 = first(z0, map.min.y), j1 = first(z1, map.min.y) - 1;
    if (i1 < i0 || j1 < j0) { // narrower than a texel: the one under the centre
        i0 = i1 = int(std::floor((0.5f * (x0 + x1) - map.min.x) / map.texelSize));
        j0 = j1 = int(std::floor((0.5f * (z0 + z1) - map.min.y) / map.texelSize));
    }
    float top = -std::numeric_limits<float>::infinity();
    for (int j = std::max(j0, 0); j <= std::min(j1, map.size - 1); ++j)
        for (int i = std::max(i0, 0); i <= std::min(i1, map.size - 1); ++i)
            top = std::max(top, map.height[std::size_t(i) + std::size_t(map.size) * std::size_t(j)]);
    return top;
}

int skyInjectionCell(const GridFrame& grid, const HeightMap& map, int x, int z) {
    const float x0 = grid.origin.x + float(x) * grid.cellSize, z0 = grid.origin.z + float(z) * grid.cellSize;
    const float top = columnTop(map, x0, z0, x0 + grid.cellSize, z0 + grid.cellSize);
    const float above = std::floor((top - grid.origin.y) / grid.cellSize) + 1.0f;
    const int y = int(std::clamp(above, 0.0f, float(grid.n)));
    return y < grid.n ? y : -1;
}

ShGrid injectSky(const GridFrame& grid, const HeightMap& map, const glm::vec3& radiance) {
    ShGrid out(grid.n);
    const glm::vec4 lobe = sh::cosineLobe({0.0f, -1.0f, 0.0f}); // light travelling down
    for (int z = 0; z < grid.n; ++z)
        for (int x = 0; x < grid.n; ++x) {
            const int y = skyInjectionCell(grid, map, x, z);
            if (y < 0)
                continue;
            // Intensity Phi / pi * cosine lobe, Phi = pi L s^2.
            for (int c = 0; c < 3; ++c)
                out.at(c, x, y, z) += radiance[c] * grid.cellSize * grid.cellSize * lobe;
        }
    return out;
}

ShGrid propagateStep(const ShGrid& source, const GvGrid* gv, const NormalGrid* normals) {
    const int n = source.n;
    ShGrid out(n);
    const auto& faces = propagationFaces();
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::ivec3 p(x, y, z);
                std::array<dvec4, 3> sum{dvec4(0.0), dvec4(0.0), dvec4(0.0)};
                for (const PropagationFace& f : faces) {
                    const glm::ivec3 q = p - f.travel;
                    if (!source.inside(q.x, q.y, q.z))
                        continue; // nothing comes from outside the cascade
                    // The light crosses the face between q and p, whose centre is q + 0.5 + 0.5 d.
                    const float t = gv ? transmittance(*gv, glm::vec3(q) + 0.5f + 0.5f * glm::vec3(f.travel),
                                                       f.direction)
                                       : 1.0f;
                    // Directed propagation: less of what heads back into the emitting surface.
                    const float directed = normals ? directedWeight(f.normal, normals->at(x, y, z)) : 1.0f;
                    const dvec4 lobe(sh::cosineLobe(f.normal) * directed);
                    for (int c = 0; c < 3; ++c) {
                        // Negative lobes are an artefact of two bands: they carry no light.
                        const double intensity =
                            std::max(0.0, double(sh::evaluate(source.at(c, q.x, q.y, q.z), f.direction)));
                        const double flux = double(f.solidAngle) * intensity * double(t);
                        // Re-emitted as a point light behind the face, facing through it.
                        sum[c] += (flux / double(sh::kPi)) * lobe;
                    }
                }
                for (int c = 0; c < 3; ++c)
                    out.at(c, x, y, z) = glm::vec4(sum[c]);
            }
    return out;
}

ShGrid propagateAndAccumulate(const ShGrid& injected, const GvGrid* gv, int steps, const NormalGrid* normals,
                              bool occludeFirstStep) {
    ShGrid accumulated = injected;
    ShGrid current = injected;
    for (int i = 0; i < steps; ++i) {
        current = propagateStep(current, i == 0 && !occludeFirstStep ? nullptr : gv, normals);
        accumulated += current;
    }
    return accumulated;
}

double totalFlux(const ShGrid& grid, int channel) {
    double dc = 0.0;
    for (const glm::vec4& v : grid.channel[channel])
        dc += double(v.x);
    return dc * kDcToFlux;
}

glm::vec4 sampleTrilinear(const ShGrid& grid, int channel, const glm::vec3& u) {
    // Texel centres at integer + 0.5; clamping to the outer centres is GL's CLAMP_TO_EDGE.
    const glm::vec3 v = glm::clamp(u - 0.5f, glm::vec3(0.0f), glm::vec3(float(grid.n - 1)));
    const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(v)), glm::ivec3(grid.n - 1));
    const glm::ivec3 i1 = glm::min(i0 + 1, glm::ivec3(grid.n - 1));
    const glm::vec3 f = v - glm::vec3(i0);
    dvec4 sum(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c(o.x ? i1.x : i0.x, o.y ? i1.y : i0.y, o.z ? i1.z : i0.z);
        const double w = double(o.x ? f.x : 1.0f - f.x) * double(o.y ? f.y : 1.0f - f.y) *
                         double(o.z ? f.z : 1.0f - f.z);
        sum += w * dvec4(grid.at(channel, c.x, c.y, c.z));
    }
    return glm::vec4(sum);
}

glm::vec3 irradianceAt(const ShGrid& accumulated, const GridFrame& grid, const glm::vec3& x, const glm::vec3& n,
                       float lookupOffsetCells) {
    const glm::vec3 u = (x + n * (lookupOffsetCells * grid.cellSize) - grid.origin) / grid.cellSize;
    const float faceArea = grid.cellSize * grid.cellSize;
    glm::vec3 e(0.0f);
    // Kaplanyan's approximation: the intensity over the cell face area taken as radiance.
    for (int c = 0; c < 3; ++c)
        e[c] = sh::irradiance(sampleTrilinear(accumulated, c, u), n) / faceArea;
    return e;
}

} // namespace lpv::renderer::lpvref
