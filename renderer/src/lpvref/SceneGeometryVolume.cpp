#include "lpv/renderer/lpv/SceneGeometryVolume.h"
#include "lpv/renderer/lpv/ShBands.h"
#include "lpvref/SceneTriangles.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lpv::renderer::lpvref {

namespace {

int subdivisions(const detail::WorldTriangle& t, float spacing) {
    const float longest =
        std::max({glm::length(t.b - t.a), glm::length(t.c - t.b), glm::length(t.a - t.c)});
    return std::clamp(int(std::ceil(longest / spacing)), 1, 256);
}

template <class Visit>
bool visitSurfels(const detail::WorldTriangle& t, float spacing, Visit&& visit) {
    const int m = subdivisions(t, spacing);
    const float area = t.area / float(m * m);
    const glm::vec3 du = (t.b - t.a) / float(m), dv = (t.c - t.a) / float(m);
    detail::forEachSubTriangleCentroid(m, [&](float u, float v) { visit(Surfel{t.a + u * du + v * dv, t.normal, area}); });
    return true;
}

template <class Visit>
void forEachSceneSurfel(const scene::Scene& scene, float spacing, Visit&& visit) {
    detail::forEachWorldTriangle(
        scene, [](std::uint32_t) { return true; }, [&](const detail::WorldTriangle& t) { return visitSurfels(t, spacing, visit); });
}

auto everyMaterial() {
    return [](std::uint32_t) { return true; };
}

// Surfels of every object, hidden ones too: what the budget is checked against.
std::size_t countAllSurfels(const scene::Scene& scene, const std::vector<glm::mat4>& worlds, float spacing) {
    std::size_t count = 0;
    for (int o = 0; o < int(scene.objects.size()); ++o)
        detail::forEachObjectTriangle(scene, o, worlds[std::size_t(o)], everyMaterial(), [&](const detail::WorldTriangle& t) {
            const std::size_t m = std::size_t(subdivisions(t, spacing));
            count += m * m;
            return true;
        });
    return count;
}

std::uint64_t placementKey(const scene::Object& object, const glm::mat4& world) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a over the mesh, the visibility and the matrix
    auto mix = [&](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            h = (h ^ bytes[i]) * 1099511628211ull;
    };
    mix(&object.mesh, sizeof(object.mesh));
    const unsigned char visible = object.visible ? 1 : 0;
    mix(&visible, 1);
    mix(&world, sizeof(world));
    return h;
}

// Sums surfels into world cells; consecutive surfels of one triangle mostly
// fall into the cell before, so the last cell is kept at hand.
class WorldGvBuilder {
  public:
    explicit WorldGvBuilder(float cellSize, int bands = 2) : cellSize_(cellSize), bands_(bands) {}
    void add(const Surfel& s) {
        const glm::vec3 g = glm::floor(s.position / cellSize_ + 0.5f);
        if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z) ||
            glm::any(glm::greaterThan(glm::abs(g), glm::vec3(float(WorldGv::kCoordinateBias - 1)))))
            return;
        const std::uint64_t k = WorldGv::key(glm::ivec3(g));
        if (!last_ || lastKey_ != k) {
            last_ = &sums_[k];
            lastKey_ = k;
        }
        const float coverage = std::min(s.area / (cellSize_ * cellSize_), 1.0f);
        last_->low += coverage * sh::cosineLobe(s.normal);
        if (bands_ == 3) {
            const sh::Coeffs<3> lobe = sh::cosineLobeOf<3>(s.normal);
            for (std::size_t j = 0; j < 5; ++j)
                last_->band2[j] += coverage * lobe[int(j) + 4];
        }
    }
    void add(std::uint64_t key, const glm::vec4& value, const GvBand2* band2) {
        Cell& cell = sums_[key];
        cell.low += value;
        if (band2)
            for (std::size_t j = 0; j < 5; ++j)
                cell.band2[j] += (*band2)[j];
    }
    WorldGv finish() {
        std::vector<std::pair<std::uint64_t, Cell>> sorted(sums_.begin(), sums_.end());
        std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        WorldGv out;
        out.cellSize = cellSize_;
        out.cells.reserve(sorted.size());
        for (const auto& [key, cell] : sorted) {
            out.cells.emplace_back(key, cell.low);
            if (bands_ == 3)
                out.band2.push_back(cell.band2);
        }
        return out;
    }

  private:
    struct Cell {
        glm::vec4 low{0.0f};
        GvBand2 band2{}; // three bands only
    };
    float cellSize_;
    int bands_;
    std::unordered_map<std::uint64_t, Cell> sums_;
    Cell* last_ = nullptr; // stable: unordered_map never moves its elements
    std::uint64_t lastKey_ = 0;
};

} // namespace

std::vector<Surfel> sampleSceneSurfels(const scene::Scene& scene, float spacing) {
    std::vector<Surfel> out;
    forEachSceneSurfel(scene, spacing, [&](const Surfel& s) { out.push_back(s); });
    return out;
}

std::size_t countSceneSurfels(const scene::Scene& scene, float spacing) {
    std::size_t count = 0;
    detail::forEachWorldTriangle(
        scene, [](std::uint32_t) { return true; },
        [&](const detail::WorldTriangle& t) {
            const std::size_t m = std::size_t(subdivisions(t, spacing));
            count += m * m;
            return true;
        });
    return count;
}

bool WorldGv::representable(const glm::ivec3& c) {
    return glm::all(glm::lessThan(glm::abs(c), glm::ivec3(kCoordinateBias)));
}

std::uint64_t WorldGv::key(const glm::ivec3& c) {
    const auto biased = [](int v) { return std::uint64_t(std::uint32_t(v + kCoordinateBias)); };
    return (biased(c.z) << 42) | (biased(c.y) << 21) | biased(c.x);
}

glm::vec4 WorldGv::at(const glm::ivec3& c) const {
    if (!representable(c))
        return glm::vec4(0.0f);
    const std::uint64_t k = key(c);
    const auto it = std::lower_bound(cells.begin(), cells.end(), k, [](const auto& e, std::uint64_t v) { return e.first < v; });
    return it != cells.end() && it->first == k ? it->second : glm::vec4(0.0f);
}

WorldGv buildWorldGv(std::span<const Surfel> surfels, float cellSize, int bands) {
    WorldGvBuilder builder(cellSize, bands);
    for (const Surfel& s : surfels)
        builder.add(s);
    return builder.finish();
}

SceneGv buildSceneGv(const scene::Scene& scene, std::span<const float> cellSizes, std::size_t maxSurfelsPerLevel,
                     int bands) {
    SceneGvCache cache;
    cache.update(scene, cellSizes, maxSurfelsPerLevel, bands);
    return cache.gv();
}

void SceneGvCache::clear() {
    objects_.clear();
    cellSizes_.clear();
    gv_ = {};
}

int SceneGvCache::update(const scene::Scene& scene, std::span<const float> cellSizes, std::size_t maxSurfelsPerLevel,
                         int bands) {
    const std::vector<glm::mat4> worlds = scene::worldMatrices(scene);
    if (!std::equal(cellSizes.begin(), cellSizes.end(), cellSizes_.begin(), cellSizes_.end()) ||
        maxSurfelsPerLevel != maxSurfels_ || bands != bands_)
        clear();
    bands_ = bands;
    if (gv_.spacing.empty()) {
        // Two surfels per cell along an edge, coarser until the level fits its budget
        // (each triangle keeps at least one surfel).
        cellSizes_.assign(cellSizes.begin(), cellSizes.end());
        maxSurfels_ = maxSurfelsPerLevel;
        for (const float cellSize : cellSizes) {
            float spacing = 0.5f * cellSize;
            std::size_t count = countAllSurfels(scene, worlds, spacing);
            for (int widen = 0; count > maxSurfelsPerLevel && widen < 64; ++widen) {
                const std::size_t wider = countAllSurfels(scene, worlds, spacing * 1.25f);
                if (wider == count)
                    break; // one surfel per triangle already
                spacing *= 1.25f;
                count = wider;
            }
            gv_.spacing.push_back(spacing);
        }
    }
    const std::size_t levels = cellSizes_.size();
    const bool removed = objects_.size() > scene.objects.size();
    objects_.resize(scene.objects.size());
    int sampled = 0;
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        ObjectCells& cells = objects_[std::size_t(o)];
        const scene::Object& object = scene.objects[std::size_t(o)];
        const std::uint64_t placement = placementKey(object, worlds[std::size_t(o)]);
        if (cells.sampled && cells.placement == placement)
            continue;
        cells = ObjectCells{true, placement, {}, {}, {}};
        for (std::size_t k = 0; k < levels; ++k) {
            WorldGvBuilder builder(cellSizes_[k], bands_);
            std::size_t count = 0;
            if (object.visible)
                detail::forEachObjectTriangle(scene, o, worlds[std::size_t(o)], everyMaterial(),
                                              [&](const detail::WorldTriangle& t) {
                                                  return visitSurfels(t, gv_.spacing[k], [&](const Surfel& s) {
                                                      builder.add(s);
                                                      ++count;
                                                  });
                                              });
            WorldGv level = builder.finish();
            cells.levels.push_back(std::move(level.cells));
            cells.band2.push_back(std::move(level.band2));
            cells.surfels.push_back(count);
        }
        ++sampled;
    }
    if (sampled == 0 && !removed && gv_.levels.size() == levels)
        return 0;
    // The objects' cells summed, object after object (the same order every time).
    gv_.levels.clear();
    gv_.surfels.assign(levels, 0);
    for (std::size_t k = 0; k < levels; ++k) {
        WorldGvBuilder sum(cellSizes_[k], bands_);
        for (const ObjectCells& cells : objects_) {
            const std::vector<GvBand2>& band2 = cells.band2[k];
            for (std::size_t i = 0; i < cells.levels[k].size(); ++i)
                sum.add(cells.levels[k][i].first, cells.levels[k][i].second, band2.empty() ? nullptr : &band2[i]);
            gv_.surfels[k] += cells.surfels[k];
        }
        gv_.levels.push_back(sum.finish());
    }
    return sampled;
}

GvGrid windowOf(const WorldGv& world, const GridFrame& grid) {
    GvGrid out(grid.n);
    windowInto(world, grid, out.potential);
    return out;
}

namespace {

// Calls visit(cell, index) for every cell of `world` inside `grid`'s window
// of (n + 1)^3 corners: `cell` its index in the window (x fastest), `index`
// its index in world.cells.
template <typename Visit> void forEachCellInWindow(const WorldGv& world, const GridFrame& grid, Visit visit) {
    const int m = grid.n + 1;
    const glm::ivec3 base(glm::floor(grid.origin / world.cellSize + 0.5f));
    for (int z = 0; z < m; ++z)
        for (int y = 0; y < m; ++y) {
            const glm::ivec3 first = base + glm::ivec3(0, y, z), last = base + glm::ivec3(grid.n, y, z);
            if (!WorldGv::representable(first) || !WorldGv::representable(last))
                continue;
            // A row of the window is a run of consecutive keys in the sorted cells.
            const std::uint64_t lo = WorldGv::key(first), hi = WorldGv::key(last);
            auto it = std::lower_bound(world.cells.begin(), world.cells.end(), lo,
                                       [](const auto& e, std::uint64_t v) { return e.first < v; });
            const std::size_t row = std::size_t(m) * (std::size_t(y) + std::size_t(m) * std::size_t(z));
            for (; it != world.cells.end() && it->first <= hi; ++it)
                visit(row + std::size_t(it->first - lo), std::size_t(it - world.cells.begin()));
        }
}

std::size_t windowCells(const GridFrame& grid) {
    const std::size_t m = std::size_t(grid.n) + 1;
    return m * m * m;
}

} // namespace

void windowInto(const WorldGv& world, const GridFrame& grid, std::span<glm::vec4> out) {
    std::fill(out.begin(), out.end(), glm::vec4(0.0f));
    if (out.size() != windowCells(grid))
        return;
    forEachCellInWindow(world, grid, [&](std::size_t cell, std::size_t i) { out[cell] = world.cells[i].second; });
}

void windowBand2Into(const WorldGv& world, const GridFrame& grid, std::span<glm::vec4> out) {
    std::fill(out.begin(), out.end(), glm::vec4(0.0f));
    if (out.size() != 2 * windowCells(grid) || world.band2.size() != world.cells.size())
        return;
    forEachCellInWindow(world, grid, [&](std::size_t cell, std::size_t i) {
        const GvBand2& b = world.band2[i];
        out[2 * cell] = glm::vec4(b[0], b[1], b[2], b[3]);
        out[2 * cell + 1] = glm::vec4(b[4], 0.0f, 0.0f, 0.0f);
    });
}

} // namespace lpv::renderer::lpvref
