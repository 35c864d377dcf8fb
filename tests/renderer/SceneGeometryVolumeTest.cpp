// The scene's geometry volume (lpvref::SceneGv, lpv.geometrySource = scene):
// the surfels cover every visible triangle once with its area and facing its
// shading normals; a cascade's window of the world GV is what injecting the
// same surfels into that cascade gives; the budget widens the spacing and
// keeps the coverage; and both faces of a thick wall reach the GV, so it
// blocks light from either side, which the sun's and the camera's views
// (one face each) do not.
#include "TestPaths.h"

#include "lpv/importers/Importer.h"
#include "lpv/renderer/lpv/SceneGeometryVolume.h"
#include "lpv/renderer/lpv/LpvBands.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

using namespace lpv;
namespace ref = lpv::renderer::lpvref;

namespace {

// A w x d quad in the xz plane, normals `up` (+1: +y, -1: -y), wound facing +y.
scene::Mesh quad(float w, float d, float up) {
    scene::Mesh m;
    m.positions = {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}};
    m.normals.assign(4, glm::vec3(0, up, 0));
    m.indices = {0, 2, 1, 0, 3, 2};
    m.submeshes = {{0, 6, 0}};
    return m;
}

scene::Object placed(int mesh, glm::vec3 at, bool visible = true) {
    scene::Object o;
    o.mesh = mesh;
    o.transform.translation = at;
    o.visible = visible;
    return o;
}

double dcTotal(const std::vector<glm::vec4>& v) {
    double sum = 0.0;
    for (const glm::vec4& c : v)
        sum += double(c.x);
    return sum;
}

// `count` surfels at random positions within `cells` cells of the origin,
// kept a tenth of a cell away from the halfway planes where rounding could
// send one to either neighbour, with random normals and areas.
std::vector<ref::Surfel> randomSurfels(int count, float cell, int cells, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> cellIndex(-cells, cells);
    std::uniform_real_distribution<float> fraction(-0.4f, 0.4f), unit(-1.0f, 1.0f), area(0.001f, 0.1f);
    std::vector<ref::Surfel> surfels;
    for (int i = 0; i < count; ++i) {
        ref::Surfel p;
        for (int a = 0; a < 3; ++a)
            p.position[a] = (float(cellIndex(rng)) + fraction(rng)) * cell;
        glm::vec3 n(unit(rng), unit(rng), unit(rng));
        p.normal = glm::length(n) > 1e-3f ? glm::normalize(n) : glm::vec3(0, 1, 0);
        p.area = area(rng);
        surfels.push_back(p);
    }
    return surfels;
}

} // namespace

TEST(SceneSurfels, CoverEveryVisibleTriangleOnceWithItsAreaFacingItsShadingNormals) {
    scene::Scene s;
    s.meshes = {quad(2.0f, 1.0f, -1.0f), quad(1.0f, 1.0f, 1.0f)};
    s.materials.resize(1);
    s.objects = {placed(0, {1, 3, -1}), placed(1, {0, 0, 0}, false)};
    const std::vector<ref::Surfel> surfels = ref::sampleSceneSurfels(s, 0.25f);
    // Longest edge sqrt(5) = 2.24: m = 9, 81 surfels per triangle; the hidden quad gives none.
    ASSERT_EQ(surfels.size(), 162u);
    EXPECT_EQ(ref::countSceneSurfels(s, 0.25f), surfels.size());
    double area = 0.0;
    for (const ref::Surfel& p : surfels) {
        area += double(p.area);
        EXPECT_NEAR(p.normal.y, -1.0f, 1e-6f) << "the shading normals face down, the winding up";
        EXPECT_NEAR(p.position.y, 3.0f, 1e-5f);
        EXPECT_GT(p.position.x, 1.0f);
        EXPECT_LT(p.position.x, 3.0f);
        EXPECT_GT(p.position.z, -1.0f);
        EXPECT_LT(p.position.z, 0.0f);
    }
    EXPECT_NEAR(area, 2.0, 1e-5);
}

TEST(WorldGv, ACascadesWindowIsInjectingTheSameSurfelsIntoIt) {
    const float cell = 0.25f;
    const std::vector<ref::Surfel> surfels = randomSurfels(5000, cell, 20, 7);
    const ref::WorldGv world = ref::buildWorldGv(surfels, cell);
    EXPECT_GT(world.cells.size(), 1000u);
    double worst = 0.0, peak = 0.0;
    for (const glm::vec3 origin : {glm::vec3(-2.0f, -1.0f, 0.5f), glm::vec3(-5.0f, -5.0f, -5.0f), glm::vec3(1.25f, 3.0f, -4.75f)}) {
        const ref::GridFrame grid{origin, cell, 16};
        const ref::GvGrid window = ref::windowOf(world, grid);
        const ref::GvGrid injected = ref::injectSurfels(grid, surfels);
        ASSERT_EQ(window.potential.size(), injected.potential.size());
        for (std::size_t i = 0; i < window.potential.size(); ++i)
            for (int j = 0; j < 4; ++j) {
                worst = std::max(worst, double(std::abs(window.potential[i][j] - injected.potential[i][j])));
                peak = std::max(peak, double(std::abs(injected.potential[i][j])));
            }
        EXPECT_GT(dcTotal(injected.potential), 1.0) << "the cascade must hold surfels, or this compares nothing";
    }
    std::cout << "[ figures ] window against injection: max difference " << worst << " of peak " << peak << "\n";
    EXPECT_LT(worst, 1e-5 * peak);
}

// Three SH bands (lpv.shBands = 3, issue #47): the window's bands 0-1 and
// band 2 together are the CPU twin's three-band GV of the same surfels.
TEST(WorldGv, AThreeBandWindowIsTheThreeBandTwinsInjection) {
    const float cell = 0.25f;
    const std::vector<ref::Surfel> surfels = randomSurfels(3000, cell, 12, 11);
    const ref::WorldGv world = ref::buildWorldGv(surfels, cell, 3);
    ASSERT_EQ(world.band2.size(), world.cells.size());
    EXPECT_TRUE(ref::buildWorldGv(surfels, cell).band2.empty()) << "two bands keep no band 2";
    const ref::GridFrame grid{glm::vec3(-2.0f, -1.0f, 0.5f), cell, 16};
    const std::size_t m = std::size_t(grid.n) + 1, cells = m * m * m;
    std::vector<glm::vec4> low(cells), high(2 * cells);
    ref::windowInto(world, grid, low);
    ref::windowBand2Into(world, grid, high);
    const auto twin = ref::bands::injectSurfels<3>(grid, surfels);
    double worst = 0.0, peak2 = 0.0;
    for (std::size_t i = 0; i < cells; ++i) {
        const float window[9] = {low[i].x,      low[i].y,      low[i].z,      low[i].w,         high[2 * i].x,
                                 high[2 * i].y, high[2 * i].z, high[2 * i].w, high[2 * i + 1].x};
        for (int j = 0; j < 9; ++j) {
            worst = std::max(worst, double(std::abs(window[j] - twin.potential[i][j])));
            if (j >= 4)
                peak2 = std::max(peak2, double(std::abs(twin.potential[i][j])));
        }
    }
    std::cout << "[ figures ] three-band window against the twin's injection: max difference " << worst
              << ", band 2 peak " << peak2 << "\n";
    EXPECT_GT(peak2, 0.05);
    EXPECT_LT(worst, 1e-5);
}

TEST(WorldGv, AnUnsnappedCascadeReadsTheNearestWorldCells) {
    const std::vector<ref::Surfel> surfels = {{glm::vec3(1.0f, 0.5f, 0.75f), glm::vec3(0, 1, 0), 0.01f}};
    const ref::WorldGv world = ref::buildWorldGv(surfels, 0.25f);
    ASSERT_EQ(world.cells.size(), 1u);
    EXPECT_GT(world.at({4, 2, 3}).x, 0.0f);
    EXPECT_EQ(world.at({4, 2, 2}).x, 0.0f);
    // Origin 0.1 m off the grid: GV cell 0 reads world cell floor(0.4 + 0.5) = 0.
    const ref::GvGrid window = ref::windowOf(world, {glm::vec3(0.1f, 0.0f, 0.0f), 0.25f, 8});
    EXPECT_EQ(window.at(4, 2, 3), world.at({4, 2, 3}));
    EXPECT_NEAR(dcTotal(window.potential), double(world.at({4, 2, 3}).x), 1e-7);
}

TEST(SceneGv, ABudgetWidensTheSpacingAndKeepsTheCoverage) {
    scene::Scene s;
    s.meshes = {quad(4.0f, 3.0f, 1.0f)};
    s.materials.resize(1);
    s.objects = {placed(0, {0.3f, 1.1f, 0.2f})};
    const std::vector<float> cells = {0.25f, 0.5f};
    const ref::SceneGv fine = ref::buildSceneGv(s, cells, 1u << 20);
    // Longest edge 5 m: 2 x 40^2 = 3200 surfels at 0.125 m; 1000 allowed -> m <= 22, each surfel still under a cell face.
    const ref::SceneGv capped = ref::buildSceneGv(s, cells, 1000);
    ASSERT_EQ(fine.levels.size(), 2u);
    ASSERT_EQ(capped.levels.size(), 2u);
    EXPECT_FLOAT_EQ(fine.spacing[0], 0.125f);
    EXPECT_GT(capped.spacing[0], fine.spacing[0]);
    EXPECT_LE(capped.surfels[0], 1000u);
    EXPECT_EQ(fine.surfels[0], 3200u);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        // The quad's 12 m^2 over cell^2, times pi Y00: no surfel is clamped at either spacing.
        const double expected = 12.0 / (double(cells[k]) * double(cells[k])) * 0.886227;
        std::vector<glm::vec4> f, c;
        for (const auto& e : fine.levels[k].cells)
            f.push_back(e.second);
        for (const auto& e : capped.levels[k].cells)
            c.push_back(e.second);
        EXPECT_NEAR(dcTotal(f), expected, 1e-4 * expected) << "level " << k;
        EXPECT_NEAR(dcTotal(c), expected, 1e-4 * expected) << "level " << k;
    }
}

TEST(SceneGv, BothFacesOfAThickWallBlockLightFromEitherSide) {
    // A 4 x 4 m wall 0.1 m thick across x = 2 (faces at 1.95, facing -x, and
    // 2.05, facing +x), as two quads turned upright.
    scene::Scene s;
    scene::Mesh face = quad(4.0f, 4.0f, 1.0f);
    for (glm::vec3& p : face.positions)
        p = glm::vec3(p.y, p.x, p.z); // x = 0 plane; normals (0, 1, 0) -> (1, 0, 0)
    for (glm::vec3& n : face.normals)
        n = glm::vec3(n.y, n.x, n.z);
    scene::Mesh back = face;
    for (glm::vec3& n : back.normals)
        n = -n;
    s.meshes = {face, back};
    s.materials.resize(1);
    s.objects = {placed(0, {2.05f, -1.0f, -1.0f}), placed(1, {1.95f, -1.0f, -1.0f})};
    const float cell = 0.25f;
    const ref::GridFrame grid{glm::vec3(0.0f), cell, 16};
    const std::vector<float> cells = {cell};
    const ref::SceneGv sceneGv = ref::buildSceneGv(s, cells, 1u << 20);
    ref::GvGrid both = ref::windowOf(sceneGv.levels[0], grid);
    // The views' GV of a sunlit wall seen by the camera from the same side: its +x face only.
    scene::Scene oneFace = s;
    oneFace.objects[1].visible = false;
    ref::GvGrid one = ref::windowOf(ref::buildSceneGv(oneFace, cells, 1u << 20).levels[0], grid);
    // Light crossing the wall's GV plane (x = 8 cells) at mid-height, each way.
    const glm::vec3 g(8.0f, 6.5f, 6.5f);
    const glm::vec3 east(1, 0, 0), west(-1, 0, 0);
    const float bothEast = ref::transmittance(both, g, east), bothWest = ref::transmittance(both, g, west);
    const float oneEast = ref::transmittance(one, g, east), oneWest = ref::transmittance(one, g, west);
    std::cout << "[ figures ] thick wall, transmittance east / west: both faces " << bothEast << " / " << bothWest
              << ", +x face only " << oneEast << " / " << oneWest << "\n";
    EXPECT_LT(bothEast, 0.6f);
    EXPECT_LT(bothWest, 0.6f);
    EXPECT_NEAR(bothEast, bothWest, 1e-4f) << "a symmetric wall blocks both ways alike";
    EXPECT_LT(oneWest, 0.6f) << "light travelling -x meets the +x face's front";
    EXPECT_GT(oneEast, 0.99f) << "light travelling +x meets only the +x face's back, which lets it through";
}

// The editor moves one object at a time: the cache samples only that
// object again, and its sums equal a fresh build's; hiding, removing and
// adding objects likewise.
TEST(SceneGvCache, AnEditSamplesOnlyTheObjectsItChanged) {
    scene::Scene s;
    s.meshes = {quad(2.0f, 1.0f, 1.0f), quad(1.0f, 3.0f, -1.0f)};
    s.materials.resize(1);
    s.objects = {placed(0, {0, 0, 0}), placed(1, {1, 2, 0}), placed(0, {-3, 1, 1})};
    const std::vector<float> cells = {0.25f, 0.5f};
    auto same = [&](const ref::SceneGv& a, const ref::SceneGv& b) {
        if (a.levels.size() != b.levels.size())
            return false;
        for (std::size_t k = 0; k < a.levels.size(); ++k)
            if (a.levels[k].cells != b.levels[k].cells || a.surfels[k] != b.surfels[k])
                return false;
        return true;
    };
    ref::SceneGvCache cache;
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 3);
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, cells, 1u << 20)));
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 0) << "nothing changed";
    const ref::SceneGv before = cache.gv();

    s.objects[1].transform.translation.x += 0.6f;
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 1);
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, cells, 1u << 20)));
    EXPECT_FALSE(same(cache.gv(), before)) << "the moved quad must move its cells";

    s.objects[2].visible = false;
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 1);
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, cells, 1u << 20)));

    s.objects.pop_back();
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 0) << "a removed object is not sampled";
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, cells, 1u << 20)));

    s.objects.push_back(placed(1, {2, 0, 2}));
    EXPECT_EQ(cache.update(s, cells, 1u << 20), 1);
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, cells, 1u << 20)));

    const std::vector<float> other = {0.2f, 0.4f};
    EXPECT_EQ(cache.update(s, other, 1u << 20), 3) << "other cell sizes sample every object again";
    EXPECT_TRUE(same(cache.gv(), ref::buildSceneGv(s, other, 1u << 20)));
}

// Real data: Sponza (OBJ, 66,443 triangles) at the default cascades' cell
// sizes. Every surfel is smaller than a cell face, so no coverage is clamped
// away: each level's DC sums the scene's whole area (pi Y00 per cell face).
TEST(SceneGv, SponzaIsSampledWhole) {
    auto imported = importers::importScene(std::string(test::kSharedScenesDir) + "/sponza/sponza.obj");
    ASSERT_TRUE(imported) << imported.error().describe();
    const scene::Scene& s = imported->scene;
    double area = 0.0;
    for (int o = 0; o < int(s.objects.size()); ++o) {
        const scene::Object& object = s.objects[std::size_t(o)];
        if (!object.visible || object.mesh < 0)
            continue;
        const scene::Mesh& mesh = s.meshes[std::size_t(object.mesh)];
        const glm::mat4 world = s.worldMatrix(o);
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a(world * glm::vec4(mesh.positions[mesh.indices[t]], 1.0f));
            const glm::vec3 b(world * glm::vec4(mesh.positions[mesh.indices[t + 1]], 1.0f));
            const glm::vec3 c(world * glm::vec4(mesh.positions[mesh.indices[t + 2]], 1.0f));
            area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        }
    }
    const std::vector<float> cells = {0.25f, 0.5f, 1.0f, 2.0f};
    const auto start = std::chrono::steady_clock::now();
    const ref::SceneGv gv = ref::buildSceneGv(s, cells, std::size_t(1) << 24);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(gv.levels.size(), cells.size());
    std::cout << "[ figures ] Sponza: " << area << " m^2, built in " << seconds << " s;";
    for (std::size_t k = 0; k < cells.size(); ++k) {
        double dc = 0.0;
        for (const auto& e : gv.levels[k].cells)
            dc += double(e.second.x);
        const double expected = area / (double(cells[k]) * double(cells[k])) * 0.886227;
        std::cout << " level " << k << ": " << gv.surfels[k] << " surfels, " << gv.levels[k].cells.size() << " cells;";
        EXPECT_FLOAT_EQ(gv.spacing[k], 0.5f * cells[k]) << "Sponza fits the budget at every level";
        EXPECT_NEAR(dc, expected, 1e-3 * expected) << "level " << k;
    }
    std::cout << "\n";
    EXPECT_GT(gv.surfels[0], 1000000u);

    // The editor's case: one object moved, only it sampled again.
    ref::SceneGvCache cache;
    cache.update(s, cells, std::size_t(1) << 24);
    scene::Scene moved = s;
    moved.objects.back().transform.translation.y += 0.5f;
    const auto editStart = std::chrono::steady_clock::now();
    EXPECT_EQ(cache.update(moved, cells, std::size_t(1) << 24), 1);
    const double editSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - editStart).count();
    std::cout << "[ figures ] Sponza: one object moved, the scene's GV updated in " << editSeconds << " s\n";
}
